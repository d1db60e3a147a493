#!/usr/bin/env bash
# A population of rides on the demo slide (issue 11: 1000 rides in under a
# minute on a 2-core machine): the sweep of inputs/templates/sweep.nml with
# 2 body tables x RIDES/10 masses (40 ... 120 kg) x 5 flow rates (4 ... 8
# l/s), full rides (thesis tolerances, records every 0.01 s), run
#   1. in 1 thread, 2. in 2 threads, 3. in 2 MPI ranks of 1 thread each
#      (when slidesim is built with MPI and mpirun is there);
# prints wall-clock seconds, rides per second and the time 1000 rides would
# take at that pace, and the process CPU seconds per ride (user + system of
# slidesim or mpirun and its ranks): on a shared machine the wall clock
# depends on the load, CPU per ride / cores is what an idle machine gives. Run from the repository root:
#   bash bench/sweep_bench.sh BUILD_DIR [RIDES]      (RIDES a multiple of 10, default 1000)
# (bench/run.sh runs it with the default; RIDES=100 gives the rate in a tenth of the time)
set -euo pipefail
build=${1:?usage: sweep_bench.sh BUILD_DIR [RIDES]}
rides=${2:-${SWEEP_BENCH_RIDES:-1000}}
(( rides % 10 == 0 && rides >= 20 )) || { echo "RIDES must be a multiple of 10, at least 20" >&2; exit 1; }
slidesim=$(cd "$build" && pwd)/slidesim
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$slidesim" --default-input sweep | sed '/^&sweep/,$d' >base.nml
make_input() {   # name, threads
  cp base.nml "$1.nml"
  printf "&sweep\n  sex = 'male', 'female'\n  mass_range = 40.0, 120.0, %d\n  flow_rate_range = 0.004, 0.008, 5\n  threads = %d\n  progress_seconds = 60\n/\n" \
    $((rides / 10)) "$2" >>"$1.nml"
}
run() {   # label, output, command...: runs it, prints the rates
  label=$1; out=$2; shift 2
  python3 - "$label" "$out" "$rides" "$@" <<'PY'
import re, resource, subprocess, sys
label, out, rides, command = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
with open(out, "w") as f:
    subprocess.run(command, stdout=f, check=True)
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = usage.ru_utime + usage.ru_stime
text = open(out).read()
wall = float(re.search(r"wall-clock time\s+(\S+)", text).group(1))
failed = re.search(r"^\s+failed\s+(\d+)", text, re.M).group(1)
print(f"{label:<24} {rides:5d} rides {wall:8.1f} s {rides / wall:6.2f} rides/s; 1000 rides: {1000 * wall / rides:6.0f} s "
      f"(goal 60 s); CPU {cpu / rides:5.3f} s/ride; failed {failed}")
PY
}
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
make_input one 1
run "1 thread" one.out "$slidesim" -q -o one.h5 one.nml
make_input two 2
run "2 threads" two.out "$slidesim" -q -o two.h5 two.nml
if command -v mpirun >/dev/null 2>&1 && ldd "$slidesim" | grep -q libmpi; then
  make_input ranks 1
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    run "2 MPI ranks x 1 thread" ranks.out mpirun --oversubscribe -n 2 "$slidesim" -q -o ranks.h5 ranks.nml
fi
