// Failures of libmoa as one exception type carrying the status code.
using System;

namespace Moa {

/// <summary>Status codes of libmoa (moa_status); the values are part of its ABI.</summary>
public enum Status {
  Ok = 0,
  InvalidArgument = 1,
  UnknownParam = 2,
  InvalidInput = 3,
  BadState = 4,
  OutOfMemory = 5,
  Cancelled = 6,
  Io = 7,
  Internal = 8,
}

/// <summary>A libmoa call failed: <see cref="Status"/> says how, the message says why.</summary>
public sealed class MoaException : Exception {
  public MoaException(Status status, string message) : base(message) { Status = status; }

  public Status Status { get; }

  /// <summary>The C name of the status, e.g. "MOA_ERROR_UNKNOWN_PARAM".</summary>
  public string StatusName => NativeContext.status_name((int)Status);
}

}
