# Shared by run_bench.sh and demo_meshes.sh (sourced, with $root set to the project root): both
# build into the same directory, so they must configure it alike, or each would rebuild it.

# configure_bench BUILD LOGS: the Release build of the library, the tool and the benchmark
# runners (peers whose libraries are installed); the log goes to LOGS/configure.log.
configure_bench() {
  cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=Release -DMOA_BUILD_BENCH=ON \
    -DMOA_BUILD_TESTS=OFF -DMOA_BUILD_CLI=ON -DMOA_BUILD_BINDINGS=OFF >"$2/configure.log" 2>&1 ||
    { cat "$2/configure.log" >&2; exit 1; }
}

# build_bench BUILD LOGS JOBS TARGET...: builds the targets; the log goes to LOGS/build.log.
build_bench() {
  local build=$1 logs=$2 jobs=$3
  shift 3
  cmake --build "$build" --target "$@" -j "$jobs" >"$logs/build.log" 2>&1 ||
    { tail -n 30 "$logs/build.log" >&2; exit 1; }
}

# code_revision [PATH...]: the short commit of HEAD, "with uncommitted changes" when the given
# paths (the whole tree without any) differ from it; "unknown" outside a git checkout.
code_revision() {
  local revision
  revision=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
  if [[ $revision != unknown && -n $(git -C "$root" status --porcelain -- "$@" 2>/dev/null) ]]; then
    revision="$revision with uncommitted changes"
  fi
  echo "$revision"
}
