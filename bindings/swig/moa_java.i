// Java part of moa.i. The generated classes are package-private helpers of org.libmoa's public
// classes (bindings/java/src); Reconstructor frees native memory in close() or through a Cleaner,
// so the proxies get no finalize().

%typemap(javaclassmodifiers) SWIGTYPE "class"
%pragma(java) moduleclassmodifiers="final class"
%pragma(java) jniclassclassmodifiers="final class"
%pragma(java) jniclasscode=%{
  static {
    NativeLibrary.load();
  }
%}
%typemap(javafinalize) SWIGTYPE ""

// A Java array for a (pointer, length) pair. moa only copies from or into it, without calling
// back into Java meanwhile, so the critical (usually copy-free) access is allowed. MODE is
// JNI_ABORT for input arrays (nothing to write back) and 0 for output arrays.
%define MOA_JAVA_ARRAY(PTR, LEN, JNITYPE, JTYPE, MODE)
%typemap(jni) (PTR, LEN) "JNITYPE"
%typemap(jtype) (PTR, LEN) "JTYPE"
%typemap(jstype) (PTR, LEN) "JTYPE"
%typemap(javain) (PTR, LEN) "$javainput"
%typemap(in) (PTR, LEN) {
  if (!$input) {
    SWIG_JavaThrowException(jenv, SWIG_JavaNullPointerException, "array is null");
    return $null;
  }
  $2 = (size_t)jenv->GetArrayLength($input);
  $1 = ($1_ltype)jenv->GetPrimitiveArrayCritical($input, 0);
  if (!$1) return $null;  // an OutOfMemoryError is pending
}
%typemap(freearg) (PTR, LEN) "jenv->ReleasePrimitiveArrayCritical($input, (void *)$1, MODE);"
%enddef

MOA_JAVA_ARRAY(const double *xyz, size_t length, jdoubleArray, double[], JNI_ABORT)
MOA_JAVA_ARRAY(const float *xyz, size_t length, jfloatArray, float[], JNI_ABORT)
MOA_JAVA_ARRAY(double *out, size_t capacity, jdoubleArray, double[], 0)
MOA_JAVA_ARRAY(int *out, size_t capacity, jintArray, int[], 0)

// Java has its own route for progress: the director.
%ignore moa_swig::NativeContext::set_progress_function;
