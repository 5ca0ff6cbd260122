// The tests switch the progress route (see Progress.cs) through internals.
using System.Runtime.CompilerServices;

[assembly: InternalsVisibleTo("MoaTests")]
