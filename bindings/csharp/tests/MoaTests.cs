// Tests of the C# binding, run by CTest under mono. Exit code 0 when every test passes.
// The first argument "static" forces the progress route Unity's IL2CPP takes (see Progress.cs).
using System;
using System.Collections.Generic;
using Moa;

internal static class MoaTests {
  private const int SpherePoints = 500;

  // Fibonacci points on a sphere of radius 2: an evenly sampled closed surface.
  private static double[] Sphere(int n) {
    var xyz = new double[3 * n];
    double golden = Math.PI * (3.0 - Math.Sqrt(5.0));
    for (int i = 0; i < n; ++i) {
      double y = 1.0 - 2.0 * (i + 0.5) / n;
      double r = Math.Sqrt(1.0 - y * y);
      xyz[3 * i] = 2.0 * r * Math.Cos(golden * i);
      xyz[3 * i + 1] = 2.0 * y;
      xyz[3 * i + 2] = 2.0 * r * Math.Sin(golden * i);
    }
    return xyz;
  }

  private static void Assert(bool condition, string what) {
    if (!condition) throw new Exception("assertion failed: " + what);
  }

  private static T Throws<T>(Action action) where T : Exception {
    try {
      action();
    } catch (T e) {
      return e;
    }
    throw new Exception("expected " + typeof(T).Name);
  }

  private static void CheckMesh(Mesh mesh, int points) {
    Assert(mesh.VertexCount == points, "vertex count " + mesh.VertexCount);
    Assert(mesh.Vertices.Length == 3 * points, "vertex array length");
    Assert(mesh.TriangleCount > points, "triangle count " + mesh.TriangleCount);
    Assert(mesh.Triangles.Length == 3 * mesh.TriangleCount, "index array length");
    for (int t = 0; t < mesh.TriangleCount; ++t) {
      int a = mesh.Triangles[3 * t], b = mesh.Triangles[3 * t + 1], c = mesh.Triangles[3 * t + 2];
      Assert(a >= 0 && a < points && b >= 0 && b < points && c >= 0 && c < points, "index range");
      Assert(a != b && b != c && c != a, "distinct corners");
    }
  }

  private static void SphereDouble() {
    double[] xyz = Sphere(SpherePoints);
    using (var r = new Reconstructor()) {
      r.SetPoints(xyz);
      Mesh mesh = r.Run();
      CheckMesh(mesh, SpherePoints);
      for (int i = 0; i < xyz.Length; ++i) Assert(mesh.Vertices[i] == xyz[i], "vertices are the points");
    }
  }

  private static void SphereFloat() {
    double[] xyz = Sphere(SpherePoints);
    var single = new float[xyz.Length];
    for (int i = 0; i < xyz.Length; ++i) single[i] = (float)xyz[i];
    using (var r = new Reconstructor()) {
      r.SetPoints(single);
      CheckMesh(r.Run(), SpherePoints);
    }
  }

  private static void Parameters() {
    using (var r = new Reconstructor()) {
      r.SetParam("neighbors", 24);
      Assert(r.GetParam("neighbors") == 24, "a parameter keeps its value");
      var e = Throws<MoaException>(() => r.SetParam("no_such_param", 1));
      Assert(e.Status == Status.UnknownParam, "status " + e.Status);
      Assert(e.StatusName == "MOA_ERROR_UNKNOWN_PARAM", "status name " + e.StatusName);
      Assert(e.Message.Contains("no_such_param"), "message names the parameter: " + e.Message);
      e = Throws<MoaException>(() => r.SetParam("neighbors", 1e9));
      Assert(e.Status == Status.InvalidArgument, "out of range: " + e.Status);
      Assert(e.Message.Contains("neighbors"), "message: " + e.Message);
    }
    var names = new List<string>();
    foreach (ParameterInfo p in Reconstructor.Parameters) names.Add(p.Name);
    Assert(names.Contains("neighbors") && names.Contains("threads"), "parameter table");
  }

  private static void BadInput() {
    using (var r = new Reconstructor()) {
      var e = Throws<MoaException>(() => r.SetPoints(new double[10]));
      Assert(e.Status == Status.InvalidArgument && e.Message.Contains("10"), e.Message);
      e = Throws<MoaException>(() => r.Run());
      Assert(e.Status == Status.BadState, "run without points: " + e.Status);
      Throws<ArgumentNullException>(() => r.SetPoints((double[])null));
    }
    var closed = new Reconstructor();
    closed.Dispose();
    closed.Dispose();
    Throws<ObjectDisposedException>(() => closed.SetParam("threads", 1));
  }

  private static void CancelThenRunAgain() {
    using (var r = new Reconstructor()) {
      r.SetPoints(Sphere(SpherePoints));
      var stages = new List<Stage>();
      bool cancel = true;
      r.Progress += (sender, e) => {
        Assert(sender == r, "sender");
        Assert(e.Fraction >= 0 && e.Fraction <= 1, "fraction");
        stages.Add(e.Stage);
        if (cancel && e.Stage == Stage.Mesh) e.Cancel = true;
      };
      var error = Throws<MoaException>(() => r.Run());
      Assert(error.Status == Status.Cancelled, "status " + error.Status);
      Assert(stages.Contains(Stage.Mesh) && !stages.Contains(Stage.Finish), "stopped at mesh");

      cancel = false;
      stages.Clear();
      CheckMesh(r.Run(), SpherePoints);
      Assert(stages[0] == Stage.Points && stages[stages.Count - 1] == Stage.Finish, "every stage");
    }
  }

  private static void HandlerExceptionPropagates() {
    using (var r = new Reconstructor()) {
      r.SetPoints(Sphere(SpherePoints));
      r.Progress += (sender, e) => { throw new InvalidOperationException("from the handler"); };
      var e2 = Throws<InvalidOperationException>(() => r.Run());
      Assert(e2.Message == "from the handler", e2.Message);
    }
  }

  private static int Main(string[] args) {
    if (args.Length > 0 && args[0] == "static") ProgressRelay.UseStaticRoute = true;
    var tests = new Dictionary<string, Action> {
      { "sphere_double", SphereDouble },
      { "sphere_float", SphereFloat },
      { "parameters", Parameters },
      { "bad_input", BadInput },
      { "cancel_then_run_again", CancelThenRunAgain },
      { "handler_exception_propagates", HandlerExceptionPropagates },
    };
    int failed = 0;
    foreach (var test in tests) {
      try {
        test.Value();
        Console.WriteLine("ok   " + test.Key);
      } catch (Exception e) {
        ++failed;
        Console.WriteLine("FAIL " + test.Key + ": " + e);
      }
    }
    // The static route must not have been chosen behind the tests' back under mono.
    bool expectStatic = args.Length > 0 && args[0] == "static";
    if (ProgressRelay.UseStaticRoute != expectStatic) {
      ++failed;
      Console.WriteLine("FAIL progress route: static = " + ProgressRelay.UseStaticRoute);
    }
    Console.WriteLine("libmoa " + Reconstructor.Version + ": " + failed + " failed");
    return failed == 0 ? 0 : 1;
  }
}
