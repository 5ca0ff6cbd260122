// The one SWIG interface of libmoa's bindings. It wraps the small C++ layer of moa_swig.hpp
// rather than moa.h itself: that layer turns (pointer, count) pairs into single array arguments,
// keeps errors as status codes that each language's own layer turns into its exception type,
// and hosts the progress hook that directors subclass. Typemaps that only make sense for one
// language live in moa_<language>.i beside this file.
#if defined(SWIGLUA)
%module moa  // Lua has no directors; its progress hook is a native function (moa_lua.i)
#else
%module(directors="1") moa
#endif

%{
#include "moa_swig.hpp"
%}

%include "typemaps.i"

// Target languages subclass the progress hook (not in Lua, which has no directors).
%feature("director") moa_swig::NativeProgress;
// Not copyable; the raw mesh pointers serve only Lua's hand-written natives (moa_lua.i).
%ignore moa_swig::NativeContext::NativeContext(const NativeContext &);
%ignore moa_swig::NativeContext::operator=;
%ignore moa_swig::NativeContext::vertex_data;
%ignore moa_swig::NativeContext::triangle_data;

// get_param's value comes back as the language's out-parameter (C#: out double, Java: double[1],
// Lua: a second result).
%apply double *OUTPUT { double *value };

#if defined(SWIGCSHARP)
%include "moa_csharp.i"
#elif defined(SWIGJAVA)
%include "moa_java.i"
#elif defined(SWIGLUA)
%include "moa_lua.i"
#else
#error "libmoa has bindings for C#, Java and Lua only"
#endif

// NativeParam describes the table; nothing writes to it.
%immutable;
%include "moa_swig.hpp"
%mutable;
