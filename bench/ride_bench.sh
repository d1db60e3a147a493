#!/usr/bin/env bash
# The ride on the demo slide vs the thesis's 10.98 s CPU for a 15.8 s ride
# (run by bench/run.sh with the build folder as $1; run from the repository
# root):
# 1. the library runs (bench/ride_bench.f90): the water, the ride in variants,
#    the rider's cost per simulated second next to the sled's;
# 2. the whole default run as a user starts it (`slidesim` with no argument:
#    reading, fitting the slide, the water, the rider, the evaluation, the
#    result and XDMF files), its process CPU time (user + system), median of
#    11 runs. Goal: 0.2 s.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
build=${1:?usage: ride_bench.sh BUILD_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
ride_bench=$(bench_program "$build" ride_bench)
"$ride_bench"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
slidesim=$(cd "$build" && pwd)/slidesim
cd "$work"
read -r whole user system low high < <(python3 "$root/bench/support/process_cpu.py" 11 "$slidesim" -q -o "$work/default.h5")
printf '%-44s %8.4f s (user %.4f, system %.4f; min %.4f, max %.4f)\n' \
  'whole default ride, process CPU, median of 11' "$whole" "$user" "$system" "$low" "$high"
awk -v t="$whole" 'BEGIN { printf "%-44s %8.1f (thesis 10.98 s for a 15.8 s ride; goal 0.2 s)\n", "  thesis/ours", 10.98/t }'
