// The public face of the C# binding: one reconstruction context.
using System;
using System.Collections.Generic;
using System.Runtime.ExceptionServices;
using System.Runtime.InteropServices;

namespace Moa {

/// <summary>
/// Reconstructs a triangle mesh from points. Use one instance from one thread at a time;
/// distinct instances may run concurrently. Dispose it to free the native context at once.
/// </summary>
public sealed class Reconstructor : IDisposable {
  private NativeContext native;

  /// <exception cref="MoaException">libmoa could not create a context.</exception>
  public Reconstructor() {
    var created = new NativeContext();
    int status = created.open();
    if (status != 0) {
      string message = created.last_error();
      created.Dispose();
      throw new MoaException((Status)status, message);
    }
    native = created;
  }

  /// <summary>Version of the native library, "MAJOR.MINOR.PATCH".</summary>
  public static string Version => NativeContext.version();

  /// <summary>libmoa's parameters with their defaults and ranges.</summary>
  public static IReadOnlyList<ParameterInfo> Parameters {
    get {
      var list = new List<ParameterInfo>();
      uint count = NativeContext.param_count();
      for (uint i = 0; i < count; ++i) {
        using (NativeParam p = NativeContext.param_info(i)) list.Add(new ParameterInfo(p));
      }
      return list;
    }
  }

  /// <summary>Raised on the thread that called Run while it runs; may cancel it.</summary>
  public event EventHandler<ProgressEventArgs> Progress;

  /// <summary>Gives the points (copied): x, y, z per point. Discards the last mesh.</summary>
  public void SetPoints(double[] xyz) {
    if (xyz == null) throw new ArgumentNullException(nameof(xyz));
    Check(Native.set_points(xyz, (uint)xyz.Length));
  }

  /// <summary>Same from single precision, e.g. a flattened array of Unity Vector3s.</summary>
  public void SetPoints(float[] xyz) {
    if (xyz == null) throw new ArgumentNullException(nameof(xyz));
    Check(Native.set_points_float(xyz, (uint)xyz.Length));
  }

  /// <summary>Sets a parameter by name; it keeps its value across runs and point sets.</summary>
  /// <exception cref="MoaException">Status.UnknownParam for an unknown name,
  /// Status.InvalidArgument for a value out of range.</exception>
  public void SetParam(string name, double value) {
    if (name == null) throw new ArgumentNullException(nameof(name));
    Check(Native.set_param(name, value));
  }

  public double GetParam(string name) {
    if (name == null) throw new ArgumentNullException(nameof(name));
    double value;
    Check(Native.get_param(name, out value));
    return value;
  }

  /// <summary>Reconstructs the mesh of the points with the current parameters.</summary>
  /// <exception cref="MoaException">The run failed or a progress handler cancelled it; the
  /// reconstructor stays usable.</exception>
  public Mesh Run() {
    NativeContext ctx = Native;
    EventHandler<ProgressEventArgs> handler = Progress;
    if (handler == null) {
      ctx.set_listener(null);
      Check(ctx.run());
      return ReadMesh(ctx);
    }

    var relay = new ProgressRelay(this, handler);
    ProgressDirector director = relay.TryDirector();
    GCHandle handle = default(GCHandle);
    int status;
    try {
      if (director != null) {
        ctx.set_listener(director);
      } else {
        handle = GCHandle.Alloc(relay);
        ctx.set_progress_function(ProgressRelay.StaticCallback, GCHandle.ToIntPtr(handle));
      }
      status = ctx.run();
    } finally {
      ctx.set_listener(null);
      if (director != null) director.Dispose();
      if (handle.IsAllocated) handle.Free();
    }
    // The handler's own exception explains the cancellation better than libmoa can.
    if (relay.Failure != null) ExceptionDispatchInfo.Capture(relay.Failure).Throw();
    Check(status);
    return ReadMesh(ctx);
  }

  public void Dispose() {
    if (native != null) native.Dispose();
    native = null;
  }

  private NativeContext Native {
    get {
      if (native == null) throw new ObjectDisposedException(nameof(Reconstructor));
      return native;
    }
  }

  private Mesh ReadMesh(NativeContext ctx) {
    var vertices = new double[checked(3 * (int)ctx.vertex_count())];
    var triangles = new int[checked(3 * (int)ctx.triangle_count())];
    Check(ctx.copy_vertices(vertices, (uint)vertices.Length));
    Check(ctx.copy_triangles(triangles, (uint)triangles.Length));
    return new Mesh(vertices, triangles);
  }

  private void Check(int status) {
    if (status != 0) throw new MoaException((Status)status, native.last_error());
  }
}

}
