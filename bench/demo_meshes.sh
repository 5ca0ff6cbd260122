#!/usr/bin/env bash
# Meshes that no test and no benchmark input is made from: the vertices of every mesh of
# 300-50,000 vertices in CGAL's demo data (Debian's libcgal-demo) but those of the shared data
# (which come from there too), reconstructed by libmoa and, when its runner is built, by CGAL's
# advancing front. `moa check` looks at each result and at each mesh the vertices came from; the
# report puts them side by side. See bench/README.md.
set -euo pipefail

usage() {
  cat <<'EOF'
Usage: bench/demo_meshes.sh [options]
  --build DIR    build directory (default /tmp/build-bench, shared with run_bench.sh)
  --work DIR     the meshes, results and logs (default /tmp/moa-demo-meshes)
  --out FILE     the report (default bench/results/demo_meshes.md)
  --timeout S    seconds allowed to one run (default 300)
  --jobs N       parallel build jobs (default: nproc)
  --data DIR     the shared data, whose meshes are left out (default ../shared/data)
Needs libcgal-demo (its data archive); installs it with apt-get when run as root.
EOF
}

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/bench/build_bench.sh"
build=/tmp/build-bench
work=/tmp/moa-demo-meshes
out="$root/bench/results/demo_meshes.md"
timeout_s=300
jobs=$(nproc)
data="$root/../shared/data"
while (($#)); do
  case $1 in
    --build) build=$2; shift ;;
    --work) work=$2; shift ;;
    --out) out=$2; shift ;;
    --timeout) timeout_s=$2; shift ;;
    --jobs) jobs=$2; shift ;;
    --data) data=$2; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "demo_meshes.sh: unknown argument $1" >&2; usage >&2; exit 2 ;;
  esac
  shift
done

archive=/usr/share/doc/libcgal-dev/data.tar.gz
if [[ ! -f $archive ]]; then
  if ((EUID == 0)); then
    apt-get install -y libcgal-demo >/dev/null
  else
    echo "demo_meshes.sh: $archive is missing; install libcgal-demo (apt-get install libcgal-demo)" >&2
    exit 1
  fi
fi

rm -rf "$work/meshes" "$work/results" "$work/logs"
mkdir -p "$work/meshes" "$work/results" "$work/logs"
tar -xzf "$archive" -C "$work/meshes" --strip-components=2 --wildcards 'data/meshes/*.off'

echo "== configure and build in $build"
configure_bench "$build" "$work/logs"
targets=(moa_cli)
cgal=0
if grep -q $'^cgal_afront\t1\t' "$build/bench/peers.tsv"; then
  targets+=(cgal_afront)
  cgal=1
fi
build_bench "$build" "$work/logs" "$jobs" "${targets[@]}"
moa="$build/src/cli/moa"

# The vertex count is the first number after the OFF keyword (comments and blank lines aside).
vertex_count() {
  awk '/^[[:space:]]*(#|$)/ {next} {sub(/^[[:space:]]*[A-Z]*OFF/, ""); if (NF) {print $1; exit}}' "$1"
}

names=() shared=()
for mesh in "$work"/meshes/*.off; do
  n=$(vertex_count "$mesh") name=$(basename "$mesh" .off)
  [[ $n =~ ^[0-9]+$ ]] && ((n >= 300 && n <= 50000)) || continue
  if [[ -f $data/meshes/$name.off ]]; then shared+=("$name"); else names+=("$name"); fi
done
echo "== ${#names[@]} meshes of 300-50,000 vertices (left out, as in the shared data: ${shared[*]:-none})"

# Changes count only where they can change the results: the library, the tool, the build and
# this script (not the reports in bench/results, nor the documentation).
revision=$(code_revision src include cmake CMakeLists.txt bench/CMakeLists.txt \
  bench/cgal_afront.cpp bench/build_bench.sh bench/demo_meshes.sh bench/demo_meshes_report.py)
for name in "${names[@]}"; do
  mesh="$work/meshes/$name.off" res="$work/results/$name"
  "$moa" check "$mesh" --json >"$res.reference.json" 2>"$work/logs/$name.reference.log" || true
  if timeout "$timeout_s" "$moa" reconstruct "$mesh" -o "$res.moa.ply" --stats "$res.moa.stats.json" \
    --quiet 2>"$work/logs/$name.moa.log"; then
    "$moa" check "$res.moa.ply" --json >"$res.moa.json" 2>>"$work/logs/$name.moa.log" || true
  fi
  if ((cgal)); then
    : >"$res.cgal.tried"  # a run that fails or times out leaves only this
    start=$(date +%s.%N)
    if timeout "$timeout_s" "$build/bench/cgal_afront" "$mesh" --mesh "$res.cgal.off" \
      >"$work/logs/$name.cgal.log" 2>&1; then
      awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {print b - a}' >"$res.cgal.seconds"
      "$moa" check "$res.cgal.off" --json >"$res.cgal.json" 2>>"$work/logs/$name.cgal.log" || true
    fi
  fi
  echo "   $name"
done

mkdir -p "$(dirname "$out")"
SHARED_LEFT_OUT="${shared[*]:-}" python3 "$root/bench/demo_meshes_report.py" "$work/results" \
  "$revision" "${names[@]}" >"$out"
echo "== report: $out"
