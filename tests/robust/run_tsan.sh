#!/usr/bin/env bash
# Builds libmoa and tests/robust/test_robust_threads.cpp with ThreadSanitizer in BUILD_DIR and
# runs that test: several contexts on several threads, with callbacks, cancellation and worker
# threads. Any race report fails it (halt_on_error). The tests without worker threads run with
# no suppression; tsan.supp beside this script waives, for the others, only what TSan cannot
# judge in an uninstrumented libtbb.
# Usage: bash tests/robust/run_tsan.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
source_dir=$PWD
if (($# != 1)); then
  sed -n '2,6p' "$0" >&2
  exit 2
fi
build=$(realpath -m "$1")
mkdir -p "$(dirname "$build")"  # for the configure log beside it

# GCC's TSan, like the rest of the suite. -O1: TSan is slow enough without -O0.
flags="-fsanitize=thread -g -O1"
cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread -DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=thread \
  -DMOA_BUILD_TESTS=ON -DMOA_BUILD_CLI=OFF -DMOA_BUILD_BINDINGS=OFF -DMOA_BUILD_BENCH=OFF \
  -DCMAKE_UNITY_BUILD=ON \
  > "$build.configure.log" || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j"$(nproc)" --target robust_threads

options="halt_on_error=1 second_deadlock_stack=1 history_size=4"
# Contexts whose runs use no worker threads: no suppression at all.
TSAN_OPTIONS="$options" "$build/tests/robust/robust_threads" --skip '*workers*'
# Runs with TBB workers: see tsan.supp for the one waiver and why.
TSAN_OPTIONS="$options suppressions=$source_dir/tests/robust/tsan.supp" \
  "$build/tests/robust/robust_threads" --only '*workers*'
