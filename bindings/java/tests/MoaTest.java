// Tests of the Java binding, run by CTest with java -Xcheck:jni. Exit status 0 when all pass.
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.libmoa.Mesh;
import org.libmoa.MoaException;
import org.libmoa.ParameterInfo;
import org.libmoa.Reconstructor;
import org.libmoa.Stage;
import org.libmoa.Status;

public final class MoaTest {
  private static final int SPHERE_POINTS = 500;

  /** Fibonacci points on a sphere of radius 2: an evenly sampled closed surface. */
  static double[] sphere(int n) {
    double[] xyz = new double[3 * n];
    double golden = Math.PI * (3.0 - Math.sqrt(5.0));
    for (int i = 0; i < n; ++i) {
      double y = 1.0 - 2.0 * (i + 0.5) / n;
      double r = Math.sqrt(1.0 - y * y);
      xyz[3 * i] = 2.0 * r * Math.cos(golden * i);
      xyz[3 * i + 1] = 2.0 * y;
      xyz[3 * i + 2] = 2.0 * r * Math.sin(golden * i);
    }
    return xyz;
  }

  static void check(boolean condition, String what) {
    if (!condition) throw new AssertionError(what);
  }

  interface Body {
    void run() throws Exception;
  }

  static <T extends Throwable> T expect(Class<T> type, Body body) throws Exception {
    try {
      body.run();
    } catch (Throwable t) {
      if (type.isInstance(t)) return type.cast(t);
      throw new AssertionError("expected " + type.getSimpleName() + ", got " + t, t);
    }
    throw new AssertionError("expected " + type.getSimpleName());
  }

  static void checkMesh(Mesh mesh, int points) {
    check(mesh.vertexCount() == points, "vertex count " + mesh.vertexCount());
    check(mesh.triangleCount() > points, "triangle count " + mesh.triangleCount());
    int[] t = mesh.triangles();
    check(t.length == 3 * mesh.triangleCount(), "index array length");
    for (int i = 0; i < t.length; i += 3) {
      for (int k = 0; k < 3; ++k) check(t[i + k] >= 0 && t[i + k] < points, "index range");
      check(t[i] != t[i + 1] && t[i + 1] != t[i + 2] && t[i + 2] != t[i], "distinct corners");
    }
  }

  static void sphereDouble() {
    double[] xyz = sphere(SPHERE_POINTS);
    try (Reconstructor r = new Reconstructor()) {
      r.setPoints(xyz);
      Mesh mesh = r.run();
      checkMesh(mesh, SPHERE_POINTS);
      check(java.util.Arrays.equals(mesh.vertices(), xyz), "vertices are the points");
    }
  }

  static void sphereFloat() {
    double[] xyz = sphere(SPHERE_POINTS);
    float[] single = new float[xyz.length];
    for (int i = 0; i < xyz.length; ++i) single[i] = (float) xyz[i];
    try (Reconstructor r = new Reconstructor()) {
      r.setPoints(single);
      checkMesh(r.run(), SPHERE_POINTS);
    }
  }

  static void parameters() throws Exception {
    try (Reconstructor r = new Reconstructor()) {
      r.setParam("neighbors", 24);
      check(r.getParam("neighbors") == 24, "a parameter keeps its value");
      MoaException e = expect(MoaException.class, () -> r.setParam("no_such_param", 1));
      check(e.status() == Status.UNKNOWN_PARAM, "status " + e.status());
      check(e.status().cName().equals("MOA_ERROR_UNKNOWN_PARAM"), e.status().cName());
      check(e.getMessage().contains("no_such_param"), "message: " + e.getMessage());
      e = expect(MoaException.class, () -> r.setParam("neighbors", 1e9));
      check(e.status() == Status.INVALID_ARGUMENT, "out of range: " + e.status());
    }
    List<String> names = new ArrayList<>();
    for (ParameterInfo p : Reconstructor.parameters()) names.add(p.name());
    check(names.contains("neighbors") && names.contains("threads"), "parameter table " + names);
  }

  static void badInput() throws Exception {
    try (Reconstructor r = new Reconstructor()) {
      MoaException e = expect(MoaException.class, () -> r.setPoints(new double[10]));
      check(e.status() == Status.INVALID_ARGUMENT && e.getMessage().contains("10"), e.getMessage());
      e = expect(MoaException.class, r::run);
      check(e.status() == Status.BAD_STATE, "run without points: " + e.status());
      expect(NullPointerException.class, () -> r.setPoints((double[]) null));
    }
    Reconstructor closed = new Reconstructor();
    closed.close();
    closed.close();
    expect(IllegalStateException.class, () -> closed.setParam("threads", 1));
  }

  static void cancelThenRunAgain() throws Exception {
    try (Reconstructor r = new Reconstructor()) {
      r.setPoints(sphere(SPHERE_POINTS));
      List<Stage> stages = new ArrayList<>();
      boolean[] cancel = {true};
      r.setProgressListener((stage, fraction) -> {
        check(fraction >= 0 && fraction <= 1, "fraction " + fraction);
        stages.add(stage);
        return !(cancel[0] && stage == Stage.MESH);
      });
      MoaException e = expect(MoaException.class, r::run);
      check(e.status() == Status.CANCELLED, "status " + e.status());
      check(stages.contains(Stage.MESH) && !stages.contains(Stage.FINISH), "stopped at mesh");

      cancel[0] = false;
      stages.clear();
      checkMesh(r.run(), SPHERE_POINTS);
      check(stages.get(0) == Stage.POINTS && stages.get(stages.size() - 1) == Stage.FINISH,
          "every stage " + stages);
    }
  }

  static void listenerExceptionPropagates() throws Exception {
    try (Reconstructor r = new Reconstructor()) {
      r.setPoints(sphere(SPHERE_POINTS));
      r.setProgressListener((stage, fraction) -> {
        throw new IllegalStateException("from the listener");
      });
      IllegalStateException e = expect(IllegalStateException.class, r::run);
      check(e.getMessage().equals("from the listener"), e.getMessage());
      r.setProgressListener(null);
      checkMesh(r.run(), SPHERE_POINTS);
    }
  }

  public static void main(String[] args) {
    Map<String, Body> tests = new LinkedHashMap<>();
    tests.put("sphere_double", MoaTest::sphereDouble);
    tests.put("sphere_float", MoaTest::sphereFloat);
    tests.put("parameters", MoaTest::parameters);
    tests.put("bad_input", MoaTest::badInput);
    tests.put("cancel_then_run_again", MoaTest::cancelThenRunAgain);
    tests.put("listener_exception_propagates", MoaTest::listenerExceptionPropagates);
    int failed = 0;
    for (Map.Entry<String, Body> test : tests.entrySet()) {
      try {
        test.getValue().run();
        System.out.println("ok   " + test.getKey());
      } catch (Throwable t) {
        ++failed;
        System.out.println("FAIL " + test.getKey() + ": " + t);
        t.printStackTrace(System.out);
      }
    }
    System.out.println("libmoa " + Reconstructor.version() + ": " + failed + " failed");
    System.exit(failed == 0 ? 0 : 1);
  }
}
