// The README's Java example: reconstruct a sampled sphere and report the mesh.
import org.libmoa.Mesh;
import org.libmoa.Reconstructor;

public final class Example {
  /** Fibonacci points on the unit sphere, x y z per point. */
  static double[] samplePoints(int n) {
    double[] xyz = new double[3 * n];
    for (int i = 0; i < n; ++i) {
      double y = 1 - 2 * (i + 0.5) / n, r = Math.sqrt(1 - y * y), a = i * Math.PI * (3 - Math.sqrt(5));
      xyz[3 * i] = r * Math.cos(a);
      xyz[3 * i + 1] = y;
      xyz[3 * i + 2] = r * Math.sin(a);
    }
    return xyz;
  }

  public static void main(String[] args) {
    double[] xyz = samplePoints(1000);
    // --- README example begins ---
    try (Reconstructor reconstructor = new Reconstructor()) {
      reconstructor.setPoints(xyz);                    // or a float[] of x y z
      reconstructor.setParam("neighbors", 24);
      reconstructor.setProgressListener((stage, fraction) -> {
        if (fraction == 1) System.out.println(stage + " done");
        return true;                                   // false cancels the run
      });
      Mesh mesh = reconstructor.run();                 // throws MoaException on failure
      System.out.println(mesh.vertexCount() + " vertices, " + mesh.triangleCount() + " triangles");
    }
    // --- README example ends ---
  }
}
