// The README's C# example: reconstruct a sampled sphere and report the mesh.
using System;
using Moa;

internal static class Example {
  // Fibonacci points on the unit sphere, x y z per point.
  private static double[] SamplePoints(int n) {
    var xyz = new double[3 * n];
    for (int i = 0; i < n; ++i) {
      double y = 1 - 2 * (i + 0.5) / n, r = Math.Sqrt(1 - y * y), a = i * Math.PI * (3 - Math.Sqrt(5));
      xyz[3 * i] = r * Math.Cos(a);
      xyz[3 * i + 1] = y;
      xyz[3 * i + 2] = r * Math.Sin(a);
    }
    return xyz;
  }

  private static void Main() {
    double[] xyz = SamplePoints(1000);
    // --- README example begins ---
    using (var reconstructor = new Reconstructor()) {
      reconstructor.SetPoints(xyz);                 // or a float[] of x y z
      reconstructor.SetParam("neighbors", 24);
      reconstructor.Progress += (sender, e) => {    // e.Cancel = true stops the run
        if (e.Fraction == 1) Console.WriteLine($"{e.Stage} done");
      };
      Mesh mesh = reconstructor.Run();              // throws MoaException on failure
      Console.WriteLine($"{mesh.VertexCount} vertices, {mesh.TriangleCount} triangles");
    }
    // --- README example ends ---
  }
}
