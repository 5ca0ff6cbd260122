package org.libmoa;

/** Status codes of libmoa ({@code moa_status}); the numbers are part of its ABI. */
public enum Status {
  OK,
  INVALID_ARGUMENT,
  UNKNOWN_PARAM,
  INVALID_INPUT,
  BAD_STATE,
  OUT_OF_MEMORY,
  CANCELLED,
  IO,
  INTERNAL;

  /** The status of a C code; {@link #INTERNAL} for a code this version does not know. */
  public static Status of(int code) {
    Status[] all = values();
    return code >= 0 && code < all.length ? all[code] : INTERNAL;
  }

  /** The C name, e.g. {@code "MOA_ERROR_UNKNOWN_PARAM"}. */
  public String cName() {
    return NativeContext.status_name(ordinal());
  }
}
