// Plain results: the reconstructed mesh and the description of a parameter.
namespace Moa {

/// <summary>A triangle mesh whose vertices are the input points, in input order.</summary>
public sealed class Mesh {
  internal Mesh(double[] vertices, int[] triangles) {
    Vertices = vertices;
    Triangles = triangles;
  }

  /// <summary>x, y, z per vertex.</summary>
  public double[] Vertices { get; }

  /// <summary>Three vertex indices per triangle, ready for Unity's Mesh.triangles.</summary>
  public int[] Triangles { get; }

  public int VertexCount => Vertices.Length / 3;
  public int TriangleCount => Triangles.Length / 3;
}

/// <summary>One entry of libmoa's parameter table.</summary>
public sealed class ParameterInfo {
  internal ParameterInfo(NativeParam p) {
    Name = p.name;
    Description = p.description;
    DefaultValue = p.default_value;
    MinValue = p.min_value;
    MaxValue = p.max_value;
    IsIntegral = p.integral;
  }

  public string Name { get; }
  public string Description { get; }
  public double DefaultValue { get; }
  public double MinValue { get; }
  public double MaxValue { get; }
  /// <summary>Only whole numbers are accepted.</summary>
  public bool IsIntegral { get; }
}

}
