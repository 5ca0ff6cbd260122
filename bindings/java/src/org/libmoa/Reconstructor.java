package org.libmoa;

import java.lang.ref.Cleaner;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * Reconstructs a triangle mesh from points. Use one instance from one thread at a time; distinct
 * instances may run concurrently. Close it to free the native context at once; a Cleaner frees
 * it otherwise once the instance is unreachable.
 *
 * <pre>{@code
 * try (Reconstructor r = new Reconstructor()) {
 *   r.setPoints(xyz);
 *   Mesh mesh = r.run();
 * }
 * }</pre>
 */
public final class Reconstructor implements AutoCloseable {
  private static final Cleaner CLEANER = Cleaner.create();

  private final NativeContext ctx;
  private final Cleaner.Cleanable cleanable;
  private ProgressListener listener;
  private boolean closed;

  /** @throws MoaException if libmoa could not create a context */
  public Reconstructor() {
    NativeContext created = new NativeContext();
    int status = created.open();
    if (status != 0) {
      String message = created.last_error();
      created.delete();
      throw new MoaException(Status.of(status), message);
    }
    ctx = created;
    // The action holds the proxy only, never this object, or it would never become unreachable.
    cleanable = CLEANER.register(this, created::delete);
  }

  /** Version of the native library, "MAJOR.MINOR.PATCH". */
  public static String version() {
    return NativeContext.version();
  }

  /** libmoa's parameters with their defaults and ranges. */
  public static List<ParameterInfo> parameters() {
    List<ParameterInfo> list = new ArrayList<>();
    long count = NativeContext.param_count();
    for (long i = 0; i < count; ++i) {
      NativeParam p = NativeContext.param_info(i);
      list.add(new ParameterInfo(p));
      p.delete();
    }
    return Collections.unmodifiableList(list);
  }

  /** Gives the points (copied): x, y, z per point. Discards the last mesh. */
  public void setPoints(double[] xyz) {
    check(open().set_points(requireArray(xyz)));
  }

  /** Same from single precision. */
  public void setPoints(float[] xyz) {
    check(open().set_points_float(requireArray(xyz)));
  }

  /**
   * Sets a parameter by name; it keeps its value across runs and point sets.
   *
   * @throws MoaException {@link Status#UNKNOWN_PARAM} for an unknown name,
   *     {@link Status#INVALID_ARGUMENT} for a value out of range
   */
  public void setParam(String name, double value) {
    check(open().set_param(requireName(name), value));
  }

  public double getParam(String name) {
    double[] value = new double[1];
    check(open().get_param(requireName(name), value));
    return value[0];
  }

  /** Installs a listener for the next runs; null removes it. */
  public void setProgressListener(ProgressListener listener) {
    this.listener = listener;
  }

  /**
   * Reconstructs the mesh of the points with the current parameters.
   *
   * @throws MoaException if the run failed or the listener cancelled it; the reconstructor
   *     stays usable. An exception thrown by the listener cancels the run and is rethrown here.
   */
  public Mesh run() {
    NativeContext c = open();
    ProgressBridge bridge = listener != null ? new ProgressBridge(listener) : null;
    int status;
    try {
      c.set_listener(bridge);
      status = c.run();
    } finally {
      c.set_listener(null);
      if (bridge != null) bridge.delete();
    }
    if (bridge != null && bridge.failure != null) {
      if (bridge.failure instanceof RuntimeException) throw (RuntimeException) bridge.failure;
      if (bridge.failure instanceof Error) throw (Error) bridge.failure;
      throw new RuntimeException(bridge.failure);
    }
    check(status);
    double[] vertices = new double[Math.toIntExact(3 * c.vertex_count())];
    int[] triangles = new int[Math.toIntExact(3 * c.triangle_count())];
    check(c.copy_vertices(vertices));
    check(c.copy_triangles(triangles));
    return new Mesh(vertices, triangles);
  }

  /** Frees the native context. Further calls throw IllegalStateException; closing twice is fine. */
  @Override
  public void close() {
    closed = true;
    cleanable.clean();
  }

  private NativeContext open() {
    if (closed) throw new IllegalStateException("the reconstructor is closed");
    return ctx;
  }

  private void check(int status) {
    if (status != 0) throw new MoaException(Status.of(status), ctx.last_error());
  }

  private static <T> T requireArray(T xyz) {
    if (xyz == null) throw new NullPointerException("xyz");
    return xyz;
  }

  private static String requireName(String name) {
    if (name == null) throw new NullPointerException("name");
    return name;
  }

  // The director: libmoa's progress reports arrive here through the JNI wrapper. A Java
  // exception must not travel through native frames, so it is kept, the run cancelled, and
  // run() rethrows it.
  private static final class ProgressBridge extends NativeProgress {
    private final ProgressListener listener;
    Throwable failure;

    ProgressBridge(ProgressListener listener) {
      this.listener = listener;
    }

    @Override
    public boolean on_progress(int stage, double fraction) {
      if (failure != null) return false;
      Stage known = Stage.of(stage);
      if (known == null) return true;  // a newer libmoa's stage: nothing to report it as
      try {
        return listener.onProgress(known, fraction);
      } catch (Throwable t) {
        failure = t;
        return false;
      }
    }
  }
}
