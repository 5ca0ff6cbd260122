package org.libmoa;

/**
 * A libmoa call failed: {@link #status()} says how, the message says why. Unchecked, like the
 * JDK's own argument and state errors: most failures are programming errors, and a checked
 * exception would not pass through lambdas.
 */
public class MoaException extends RuntimeException {
  private static final long serialVersionUID = 1L;
  private final Status status;

  public MoaException(Status status, String message) {
    super(message);
    this.status = status;
  }

  public Status status() {
    return status;
  }
}
