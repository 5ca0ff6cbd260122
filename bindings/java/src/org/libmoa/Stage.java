package org.libmoa;

/** Stages of a run ({@code moa_stage}), in the order they run. */
public enum Stage {
  POINTS,
  NEIGHBORS,
  MESH,
  LOOPS,
  FINISH;

  /** The stage of a C code, or null for a stage this version does not know. */
  static Stage of(int code) {
    Stage[] all = values();
    return code >= 0 && code < all.length ? all[code] : null;
  }
}
