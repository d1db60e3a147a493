#!/usr/bin/env bash
# The robust optimisation of table 4.12 (issue 29: 50 riders x 3 starts in
# under a minute on 2 cores): inputs/design/optimize_robust.nml as shipped
# (50 rides per design, the worst one's cost, 3 starts), run
#   1. in 2 threads (the shipped input), 2. in 1 thread, 3. in 2 MPI ranks of
#      1 thread each (when slidesim is built with MPI and mpirun is there);
# prints wall-clock seconds, the process CPU seconds (user + system of
# slidesim or mpirun and its ranks), the designs ridden, CPU per ride and the
# outcome. On a shared machine the wall clock depends on the load; CPU / 2 is
# what an idle 2-core machine gives. Run from the repository root:
#   bash bench/robust_bench.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: robust_bench.sh BUILD_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
slidesim=$(cd "$build" && pwd)/slidesim
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
input=$root/inputs/design/optimize_robust.nml
run() {   # label, output, command...: runs it, prints the times
  label=$1; out=$2; shift 2
  python3 - "$label" "$out" "$@" <<'PY'
import re, resource, subprocess, sys, time
label, out, command = sys.argv[1], sys.argv[2], sys.argv[3:]
start = time.monotonic()
with open(out, "w") as f:
    rc = subprocess.run(command, stdout=f, stderr=subprocess.STDOUT).returncode
wall = time.monotonic() - start
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = usage.ru_utime + usage.ru_stime
text = open(out).read()
designs = int(re.search(r"designs evaluated\s+(\d+)", text).group(1))
outcome = re.search(r"^\s+outcome\s+(.+)$", text, re.M).group(1).strip()
print(f"{label:<24} wall {wall:7.1f} s (goal 60 s)  CPU {cpu:7.1f} s  {designs} designs x 50 rides, "
      f"{1000 * cpu / (50 * designs):5.2f} ms CPU per ride; exit {rc}, {outcome}")
PY
}
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
cd "$work"
run "2 threads" two.out "$slidesim" -o two.h5 "$input"
run "1 thread" one.out "$slidesim" -o one.h5 --set optimize%threads=1 "$input"
if command -v mpirun >/dev/null 2>&1 && ldd "$slidesim" | grep -q libmpi; then
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    run "2 MPI ranks x 1 thread" ranks.out mpirun --oversubscribe -n 2 "$slidesim" -o ranks.h5 \
    --set optimize%threads=1 "$input"
fi
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
