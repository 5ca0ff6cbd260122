// C# part of moa.i. The generated classes are internal to Moa.dll; Reconstructor and friends
// (bindings/csharp/src) are the public API.
//
// Everything here keeps the assembly usable under Unity's IL2CPP, which can only call managed
// code from native code through static methods marked [MonoPInvokeCallback]:
//   - SWIG's exception and string helpers register such callbacks without the attribute, so
//     bindings/csharp/CMakeLists.txt defines SWIG_CSHARP_NO_EXCEPTION_HELPER and
//     SWIG_CSHARP_NO_STRING_HELPER; nothing below needs them.
//   - Returned strings travel as IntPtr and are read with Marshal, not through a callback.
//   - Besides the director, the progress hook accepts a static function pointer plus a handle
//     (NativeProgressFn), which is the route IL2CPP can take.

%include "arrays_csharp.i"

%typemap(csclassmodifiers) SWIGTYPE "internal class"
%pragma(csharp) moduleclassmodifiers="internal class"

// Arrays are blittable, so P/Invoke pins them instead of copying.
%apply double INPUT[] { const double *xyz };
%apply float INPUT[] { const float *xyz };
%apply double OUTPUT[] { double *out };
%apply int OUTPUT[] { int *out };

// Strings owned by libmoa (static storage or valid until the next call): copy them in C#.
%typemap(ctype, out="const char *") const char * "char *"
%typemap(imtype, out="global::System.IntPtr") const char * "string"
%typemap(out) const char * %{ $result = $1; %}
%typemap(csout, excode=SWIGEXCODE) const char * {
    string ret = global::System.Runtime.InteropServices.Marshal.PtrToStringAnsi($imcall);$excode
    return ret;
  }
%typemap(csvarout, excode=SWIGEXCODE2) const char * %{
    get {
      string ret = global::System.Runtime.InteropServices.Marshal.PtrToStringAnsi($imcall);$excode
      return ret;
    } %}

// The static progress route: a delegate declared in Progress.cs and an opaque GCHandle.
%typemap(ctype) moa_swig::NativeProgressFn "moa_swig::NativeProgressFn"
%typemap(imtype) moa_swig::NativeProgressFn "ProgressFunction"
%typemap(cstype) moa_swig::NativeProgressFn "ProgressFunction"
%typemap(csin) moa_swig::NativeProgressFn "$csinput"
%typemap(in) moa_swig::NativeProgressFn %{ $1 = $input; %}

%typemap(ctype) void *handle "void *"
%typemap(imtype) void *handle "global::System.IntPtr"
%typemap(cstype) void *handle "global::System.IntPtr"
%typemap(csin) void *handle "$csinput"
%typemap(in) void *handle %{ $1 = $input; %}
