// Progress reports of Reconstructor.Run and the two routes that carry them out of native code.
//
// Route 1, a SWIG director (ProgressDirector): native code calls a delegate bound to an instance
// method. Mono and .NET support that; Unity's IL2CPP does not and throws NotSupportedException
// when the delegate is marshalled.
// Route 2, a static function (ProgressRelay.StaticCallback) marked [MonoPInvokeCallback] that
// finds its relay through a GCHandle passed as user data. Every runtime supports it.
// Runs take route 1 where a probe at start-up shows that instance delegates marshal (and until a
// director fails to connect anyway), route 2 otherwise.
using System;
using System.Runtime.InteropServices;

namespace Moa {

/// <summary>Stages of a run (moa_stage); the values are part of libmoa's ABI.</summary>
public enum Stage {
  Points = 0,
  Neighbors = 1,
  Mesh = 2,
  Loops = 3,
  Finish = 4,
}

/// <summary>One progress report. Set <see cref="Cancel"/> to stop the run.</summary>
public sealed class ProgressEventArgs : EventArgs {
  internal ProgressEventArgs(Stage stage, double fraction) {
    Stage = stage;
    Fraction = fraction;
  }

  public Stage Stage { get; }
  /// <summary>Part of the stage done, 0 to 1.</summary>
  public double Fraction { get; }
  /// <summary>true stops the run: Run then throws MoaException with Status.Cancelled.</summary>
  public bool Cancel { get; set; }
}

// IL2CPP recognises this attribute by its name, so Moa.dll needs no reference to UnityEngine.
[AttributeUsage(AttributeTargets.Method)]
internal sealed class MonoPInvokeCallbackAttribute : Attribute {
  public MonoPInvokeCallbackAttribute(Type type) { Type = type; }
  public Type Type { get; }
}

// moa_swig::NativeProgressFn: return 0 to cancel.
[UnmanagedFunctionPointer(CallingConvention.Cdecl)]
internal delegate int ProgressFunction(IntPtr handle, int stage, double fraction);

// Delivers the reports of one run to the event handlers. Managed exceptions must not unwind
// through native frames, so a handler's exception is kept, the run cancelled, and Run rethrows.
internal sealed class ProgressRelay {
  private readonly object sender;
  private readonly EventHandler<ProgressEventArgs> handler;

  internal ProgressRelay(object sender, EventHandler<ProgressEventArgs> handler) {
    this.sender = sender;
    this.handler = handler;
  }

  internal Exception Failure { get; private set; }

  internal bool Report(int stage, double fraction) {
    if (Failure != null) return false;
    try {
      var args = new ProgressEventArgs((Stage)stage, fraction);
      handler(sender, args);
      return !args.Cancel;
    } catch (Exception e) {
      Failure = e;
      return false;
    }
  }

  // Set where directors cannot work; the tests also set it to exercise route 2 under mono.
  internal static volatile bool UseStaticRoute = !InstanceDelegatesMarshal();

  // IL2CPP refuses exactly this marshalling, and does so even where stripped reflection data
  // would keep SWIG's director from trying it.
  private static bool InstanceDelegatesMarshal() {
    try {
      ProgressFunction probe = new ProgressRelay(null, null).Probe;
      Marshal.GetFunctionPointerForDelegate(probe);
      GC.KeepAlive(probe);
      return true;
    } catch (Exception e) when (e is NotSupportedException || e is MarshalDirectiveException) {
      return false;
    }
  }

  private int Probe(IntPtr handle, int stage, double fraction) { return 1; }

  // A static field keeps the delegate (and the thunk native code calls) alive for good.
  internal static readonly ProgressFunction StaticCallback = OnProgress;

  [MonoPInvokeCallback(typeof(ProgressFunction))]
  private static int OnProgress(IntPtr handle, int stage, double fraction) {
    try {
      var relay = (ProgressRelay)GCHandle.FromIntPtr(handle).Target;
      return relay.Report(stage, fraction) ? 1 : 0;
    } catch (Exception) {
      return 0;
    }
  }

  // A director for this relay, or null where the runtime cannot marshal it (route 2 then).
  internal ProgressDirector TryDirector() {
    if (UseStaticRoute) return null;
    try {
      return new ProgressDirector(this);
    } catch (Exception e) when (e is NotSupportedException || e is MarshalDirectiveException) {
      UseStaticRoute = true;
      return null;
    }
  }
}

// Route 1: the SWIG director.
internal sealed class ProgressDirector : NativeProgress {
  private readonly ProgressRelay relay;

  internal ProgressDirector(ProgressRelay relay) { this.relay = relay; }

  public override bool on_progress(int stage, double fraction) {
    return relay.Report(stage, fraction);
  }
}

}
