#!/usr/bin/env bash
# Builds the libFuzzer targets with clang-14 (ASan + UBSan + coverage) in BUILD_DIR and runs each
# for SECONDS seconds (default 30, at most 60), as many at once as there are cores. Fails if any
# target crashes, leaks, times out or runs out of memory; the input that did it is left in
# BUILD_DIR/artifacts/ and should become a regression test in tests/fuzz/regressions/<target>/.
# Usage: bash tests/fuzz/run_fuzzers.sh BUILD_DIR [SECONDS] [TARGET...]
#   TARGET: xyz ply off obj stl run (default all)
set -euo pipefail
cd "$(dirname "$0")/../.."
source_dir=$PWD

if (($# < 1)); then
  sed -n '2,8p' "$0" >&2
  exit 2
fi
build=$(realpath -m "$1")
mkdir -p "$(dirname "$build")"  # for the configure log beside it
seconds=${2:-30}
shift $(($# >= 2 ? 2 : 1))
targets=("$@")
((${#targets[@]})) || targets=(xyz ply off obj stl run)
if ! [[ $seconds =~ ^[0-9]+$ ]] || ((seconds < 1 || seconds > 60)); then
  echo "SECONDS must be 1..60, got '$seconds'" >&2
  exit 2
fi
for tool in clang-14 clang++-14; do
  command -v "$tool" > /dev/null || { echo "$tool is missing: bash tests/install_deps.sh --robust" >&2; exit 2; }
done

# -O1 for speed, line tables for the crash reports, and no NDEBUG: asserts stay on.
flags="-O1 -gline-tables-only"
cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DMOA_SANITIZE=ON -DMOA_FUZZ=ON -DMOA_BUILD_TESTS=ON -DCMAKE_UNITY_BUILD=ON \
  -DMOA_BUILD_CLI=OFF -DMOA_BUILD_BINDINGS=OFF -DMOA_BUILD_BENCH=OFF > "$build.configure.log" \
  || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer  # function names and lines in the reports
[[ -x $symbolizer ]] && export ASAN_SYMBOLIZER_PATH=$symbolizer
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p "$build/artifacts" "$build/logs"

# One target: a scratch corpus first (new inputs go there, never into the repository), the
# seeds and the regressions after it. -rss_limit_mb catches memory blow-ups from lying sizes;
# -timeout a hang; -max_len keeps inputs near the size of the seeds; dict/ holds each format's
# keywords, which random mutation would take long to spell.
run_one() {
  local t=$1 corpus=$build/corpus/$1
  mkdir -p "$corpus"
  local dirs=("$corpus" "tests/fuzz/corpus/$t")
  [[ -d tests/fuzz/regressions/$t ]] && dirs+=("tests/fuzz/regressions/$t")
  local max_len=4096 dict=()
  [[ -f tests/fuzz/dict/$t.dict ]] && dict=(-dict="tests/fuzz/dict/$t.dict")
  [[ $t == run ]] && max_len=1206  # the header and 300 points of 1-byte or 200 of 2-byte coordinates
  "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
    -max_len=$max_len "${dict[@]}" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" \
    "${dirs[@]}" > "$build/logs/$t.log" 2>&1
}

# Each target's exit status goes to a file: simpler than tracking pids through wait -n.
jobs_at_once=$(nproc)
for t in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs_at_once)); do wait -n || true; done
  rm -f "$build/logs/$t.rc"
  (set +e; run_one "$t"; echo $? > "$build/logs/$t.rc") &
done
wait
status=0
for t in "${targets[@]}"; do
  if [[ $(cat "$build/logs/$t.rc" 2> /dev/null) == 0 ]]; then
    runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$build/logs/$t.log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz_$t: no crash in ${seconds} s ($runs inputs)"
  else
    status=1
    echo "fuzz_$t: FAILED; the end of its log ($build/logs/$t.log):"
    tail -n 60 "$build/logs/$t.log"
    ls "$build/artifacts/$t-"* 2> /dev/null | sed 's/^/  crashing input: /'
  fi
done
if ((status)); then
  echo "Add each crashing input to tests/fuzz/regressions/<target>/ once the bug is fixed."
fi
exit $status
