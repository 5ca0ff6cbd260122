package org.libmoa;

/** Receives progress reports on the thread that called {@link Reconstructor#run()}. */
@FunctionalInterface
public interface ProgressListener {
  /**
   * @param stage the running stage
   * @param fraction the part of that stage done, 0 to 1
   * @return true to go on, false to cancel the run: run() then throws a MoaException with
   *     {@link Status#CANCELLED} and the reconstructor stays usable
   */
  boolean onProgress(Stage stage, double fraction);
}
