#!/usr/bin/env bash
# The side-by-side benchmark in one command: builds libmoa's runner and the peer runners whose
# libraries are installed, writes the inputs, runs every method on every input (each run in its
# own process, under a time limit, so each peak memory figure is that run's own), checks every
# mesh with the same checker, and writes BENCHMARKS.md, bench/results/latest.md,
# bench/results/results.tsv, the plots and pictures of the meshes. See bench/README.md.
set -euo pipefail

usage() {
  cat <<'EOF'
Usage: bench/run_bench.sh [options]
  --quick           leave out the 1M-point input
  --inputs REGEX    only the inputs whose name matches REGEX (e.g. 'bunny00-')
  --methods LIST    only these methods, comma-separated, of: moa,cgal,o3d_bpa,o3d_poisson,pcl_gp3
  --timeout S       seconds allowed to one run before it counts as timed out (default 600)
  --wait-idle S     before each timed run, wait up to S seconds for other processes to leave
                    the cores idle (default 0: do not wait; the load is recorded either way)
  --build DIR       build directory (default /tmp/build-bench)
  --work DIR        inputs, meshes, logs and raw results (default /tmp/moa-bench)
  --data DIR        the shared data (default ../shared/data beside the project)
  --results DIR     where latest.md, results.tsv and the plots go (default bench/results)
  --benchmarks FILE the summary (default BENCHMARKS.md at the project root)
  --jobs N          parallel build jobs (default: nproc)
With --quick, --inputs or --methods the report goes to WORK/report unless --results and
--benchmarks say otherwise, so that a partial run never replaces the committed full results.
EOF
}

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/bench/build_bench.sh"
build=/tmp/build-bench
work=/tmp/moa-bench
data="$root/../shared/data"
results=""
benchmarks=""
quick=0
only_inputs=""
only_methods=""
timeout_s=600
wait_idle=0
jobs=$(nproc)
command_line="bench/run_bench.sh${*:+ $*}"

while (($#)); do
  case $1 in
    --quick) quick=1 ;;
    --inputs) only_inputs=$2; shift ;;
    --methods) only_methods=$2; shift ;;
    --timeout) timeout_s=$2; shift ;;
    --wait-idle) wait_idle=$2; shift ;;
    --build) build=$2; shift ;;
    --work) work=$2; shift ;;
    --data) data=$2; shift ;;
    --results) results=$2; shift ;;
    --benchmarks) benchmarks=$2; shift ;;
    --jobs) jobs=$2; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "run_bench.sh: unknown argument $1" >&2; usage >&2; exit 2 ;;
  esac
  shift
done
partial=$((quick || ${#only_inputs} || ${#only_methods}))
if ((partial)); then
  : "${results:=$work/report}" "${benchmarks:=$work/report/BENCHMARKS.md}"
else
  : "${results:=$root/bench/results}" "${benchmarks:=$root/BENCHMARKS.md}"
fi
started=$(date -u '+%Y-%m-%d %H:%M UTC')
# Idle OpenMP threads (Open3D, PCL's normals) sleep instead of spinning: on a shared machine
# spinning threads compete with the other processes and make the OpenMP peers several times
# slower (Poisson on 315 points: 11-16 s spinning, 3.6 s passive at a load of 6 on 2 cores).
# libmoa (TBB) and CGAL (sequential) are not affected. Set OMP_WAIT_POLICY to override.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE}
load_start=$(cut -d' ' -f1 /proc/loadavg)

# Only the directories this script fills are cleared, so stale results never reach the report.
rm -rf "$work/results" "$work/meshes" "$work/logs" "$work/normals"
mkdir -p "$work/results" "$work/meshes" "$work/logs" "$work/normals"

# The revision of the code that is built, read before the build: edits made while the run goes
# on do not go into it.
revision=$(code_revision)
echo "== configure and build in $build"
configure_bench "$build" "$work/logs"
grep 'bench:' "$work/logs/configure.log" || true
cp "$build/bench/peers.tsv" "$work/peers.tsv"
targets=(moa_bench moa_cli)  # the tool draws the pictures
while IFS=$'\t' read -r peer built _; do
  [[ $peer != \#* && $built == 1 ]] && targets+=("$peer")
done <"$work/peers.tsv"
build_bench "$build" "$work/logs" "$jobs" "${targets[@]}"
bench="$build/bench/moa_bench"

# The methods to run: libmoa always, each peer when its runner was built (and asked for).
methods=(moa)
have() { grep -q "^$1"$'\t1\t' "$work/peers.tsv"; }
have cgal_afront && methods+=(cgal)
have open3d_recon && methods+=(o3d_bpa o3d_poisson)
have pcl_gp3 && methods+=(pcl_gp3)
if [[ -n $only_methods ]]; then
  wanted=()
  for m in "${methods[@]}"; do [[ ,$only_methods, == *,$m,* ]] && wanted+=("$m"); done
  methods=("${wanted[@]}")
fi
echo "== methods: ${methods[*]}"
# The Poisson run reuses the ball-pivoting run's normals when both run.
share_normals=0
[[ " ${methods[*]} " == *" o3d_bpa "* && " ${methods[*]} " == *" o3d_poisson "* ]] && share_normals=1

echo "== inputs in $work"
"$bench" sample --out "$work" --data "$data" >"$work/logs/sample.log"
cat "$work/logs/sample.log"

# Busy cores over the last second, in hundredths, from /proc/stat (all processes).
busy_centicores() {
  local _c u n s i w q sq st a b
  read -r _c u n s i w q sq st _ </proc/stat
  a=$((u + n + s + q + sq + st))
  sleep 1
  read -r _c u n s i w q sq st _ </proc/stat
  b=$((u + n + s + q + sq + st))
  echo $(((b - a) * 100 / $(getconf CLK_TCK)))
}

# Waits (at most --wait-idle seconds) until the machine is practically idle.
wait_for_idle() {
  ((wait_idle > 0)) || return 0
  local start=$SECONDS busy
  while busy=$(busy_centicores); ((busy > 25)); do
    if ((SECONDS - start >= wait_idle)); then
      echo "   (machine still busy: $busy % of a core used by others; running anyway)"
      return 0
    fi
    sleep 4
  done
}

# step RESULT KEY LOG COMMAND...: runs COMMAND under the time limit. A crash, a time-out or an
# error is appended to RESULT as "KEY<TAB>failed: why" (KEY status for a reconstruction,
# analysis for the checker), which the report shows.
step() {
  local result=$1 key=$2 log=$3 rc=0
  shift 3
  [[ $key == status ]] && wait_for_idle  # only timed runs need a quiet machine
  timeout "$timeout_s" "$@" </dev/null >"$log" 2>&1 || rc=$?
  if ((rc != 0)); then
    local why="exit $rc"
    ((rc == 124)) && why="timed out after ${timeout_s} s"
    ((rc > 128 && rc != 124)) && why="killed by signal $((rc - 128))"
    printf '%s\tfailed: %s (log %s)\n' "$key" "$why" "$log" >>"$result"
    echo "   FAILED ($key): $why; last lines of $log:"
    tail -n 3 "$log" | sed 's/^/     /'
    return 1
  fi
  [[ $key == status ]] && tail -n 1 "$log" | sed 's/^/   /'
  return 0
}

# Sets `command` to the command line of one method on one input. The Open3D runs share their
# estimated normals through WORK/normals ($shared_ms: how long the ball-pivoting run took).
set_command() {
  local method=$1 file=$2 normals=$3 mesh=$4 result=$5
  local given=()
  [[ $normals != - ]] && given=(--normals "$normals")
  case $method in
    moa) command=("$bench" "$file" --threads 0 --runs 2) ;;
    cgal) command=("$build/bench/cgal_afront" "$file") ;;
    o3d_bpa)
      command=("$build/bench/open3d_recon" "$file" --method bpa "${given[@]}")
      ((share_normals)) && [[ $normals == - ]] && command+=(--save-normals "$work/normals/$name.open3d.ply")
      ;;
    o3d_poisson)
      command=("$build/bench/open3d_recon" "$file" --method poisson "${given[@]}")
      ((share_normals)) && [[ $normals == - ]] &&
        command+=(--normals "$work/normals/$name.open3d.ply" --normals-ms "$shared_ms")
      ;;
    pcl_gp3) command=("$build/bench/pcl_gp3" "$file" "${given[@]}") ;;
  esac
  command+=(--mesh "$mesh" --result "$result")
}

echo "== runs (time limit ${timeout_s} s per run)"
while IFS=$'\t' read -r -u 3 name file points _kind _source _seed large _hash normals reference _; do
  [[ $name == \#* ]] && continue
  [[ -n $only_inputs && ! $name =~ $only_inputs ]] && continue
  if ((quick && large)); then
    echo "-- $name: left out (--quick)"
    continue
  fi
  echo "-- $name ($points points)"
  for method in "${methods[@]}"; do
    result="$work/results/$name.$method.txt"
    mesh="$work/meshes/$name.$method.ply"
    printf '   %-12s' "$method"
    # Open3D's normals are estimated once per input, in the ball-pivoting run, and reused by the
    # Poisson run with their time; when they did not finish within the limit there, Poisson is
    # skipped.
    if [[ $method == o3d_poisson && $normals == - ]] && ((share_normals)); then
      shared_ms=$(sed -n 's/^normals estimated and oriented in \([0-9.]*\) ms$/\1/p' \
        "$work/logs/$name.o3d_bpa.log" 2>/dev/null || true)
      if [[ -z $shared_ms || ! -s $work/normals/$name.open3d.ply ]]; then
        printf 'status\tskipped: no Open3D normals (their estimation did not finish in the ball-pivoting run)\n' >>"$result"
        echo "skipped: no normals from the ball-pivoting run"
        continue
      fi
    fi
    set_command "$method" "$file" "$normals" "$mesh" "$result"
    if step "$result" status "$work/logs/$name.$method.log" "${command[@]}"; then
      check=("$bench" analyze "$mesh" --points "$file" --result "$result")
      [[ $reference != - ]] && check+=(--reference "$reference")
      step "$result" analysis "$work/logs/$name.$method.analyze.log" "${check[@]}" || true
    fi
  done
  if ((large)) && [[ " ${methods[*]} " == *" moa "* ]]; then
    printf '   %-12s' "moa 1 thread"
    step "$work/results/$name.moa1.txt" status "$work/logs/$name.moa1.log" \
      "$bench" "$file" --threads 1 --runs 1 --result "$work/results/$name.moa1.txt" || true
  fi
done 3<"$work/inputs.tsv"

{
  printf 'command\t%s\n' "$command_line"
  printf 'started\t%s\n' "$started"
  printf 'elapsed_s\t%s\n' "$SECONDS"
  printf 'load_start\t%s\n' "$load_start"
  printf 'load_end\t%s\n' "$(cut -d' ' -f1 /proc/loadavg)"
  printf 'revision\t%s\n' "$revision"
  printf 'timeout\t%s\n' "$timeout_s"
  printf 'omp_wait_policy\t%s\n' "$OMP_WAIT_POLICY"
} >"$work/run.tsv"

echo "== report"
mkdir -p "$results"
rm -f "$results"/*.png
rm -rf "$results/pictures"
# Pictures of every method's mesh of these inputs (INPUT:VIEW), defects highlighted, for the
# report: what the numbers mean, at a glance. A picture that fails is left out of it.
pictures=(bunny00-vertices:front fandisk-vertices:iso kitten:iso building:iso)
mkdir -p "$results/pictures"
for entry in "${pictures[@]}"; do
  name=${entry%%:*} view=${entry#*:}
  for method in "${methods[@]}"; do
    mesh="$work/meshes/$name.$method.ply"
    [[ -s $mesh ]] || continue
    picture="$results/pictures/$name.$method.png"
    timeout "$timeout_s" "$build/src/cli/moa" render "$mesh" -o "$picture" --view "$view" \
      --size 280 --highlight-defects --quiet >"$work/logs/$name.$method.picture.log" 2>&1 || {
      rm -f "$picture"  # a time-out can leave half a file, which the report would show
      echo "   picture of $name.$method failed (log $work/logs/$name.$method.picture.log)"
    }
  done
done
"$bench" report --work "$work" --results "$results" --benchmarks "$benchmarks" >/dev/null
# Debian's python3-matplotlib belongs to /usr/bin/python3, which a python3 earlier in PATH
# (pyenv, a virtualenv) may not see.
python=""
for candidate in python3 /usr/bin/python3; do
  if "$candidate" -c 'import matplotlib' 2>/dev/null; then python=$candidate; break; fi
done
if [[ -n $python ]]; then
  "$python" "$root/bench/plot.py" "$results/results.tsv" "$results" ||
    echo "plots failed; the report goes without them"
else
  echo "python3-matplotlib is not installed: no plots"
fi
# Again, now that the plots exist, so that the Markdown links them.
"$bench" report --work "$work" --results "$results" --benchmarks "$benchmarks"
echo "done in $SECONDS s"
