package org.libmoa;

/** A triangle mesh whose vertices are the input points, in input order. */
public final class Mesh {
  private final double[] vertices;
  private final int[] triangles;

  Mesh(double[] vertices, int[] triangles) {
    this.vertices = vertices;
    this.triangles = triangles;
  }

  /** x, y, z per vertex; the array belongs to this mesh, not to a copy. */
  public double[] vertices() {
    return vertices;
  }

  /** Three vertex indices per triangle. */
  public int[] triangles() {
    return triangles;
  }

  public int vertexCount() {
    return vertices.length / 3;
  }

  public int triangleCount() {
    return triangles.length / 3;
  }
}
