#!/usr/bin/env bash
# The water on the demo slide vs the thesis's 1.0 s CPU (run by bench/run.sh
# with the build folder as $1; run from the repository root):
# 1. the library run compute_water in variants (bench/water_bench.f90);
# 2. the whole default water run as a user starts it: the process `slidesim
#    inputs/water/demo_slide.nml` (the water alone; slidesim with no argument
#    runs the ride since issue 9: reading, fitting the slide, the run with
#    the edges every 0.005 s, field, table, result and XDMF files), its
#    process CPU time (user + system), median of 21 runs, next to the
#    start-up alone (`slidesim --version`).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
build=${1:?usage: water_bench.sh BUILD_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
water_bench=$(bench_program "$build" water_bench)
"$water_bench" inputs/water/demo_slide.nml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
slidesim=$(cd "$build" && pwd)/slidesim
cd "$work"
read -r whole user system low high < <(python3 "$root/bench/support/process_cpu.py" 21 "$slidesim" \
  "$root/inputs/water/demo_slide.nml" -o "$work/default.h5")
read -r start _ _ _ _ < <(python3 "$root/bench/support/process_cpu.py" 21 "$slidesim" --version)
printf '%-44s %8.4f s (user %.4f, system %.4f; min %.4f, max %.4f)\n' \
  'whole water run, process CPU, median of 21' "$whole" "$user" "$system" "$low" "$high"
printf '%-44s %8.4f s\n' '  of which start-up (slidesim --version)' "$start"
awk -v t="$whole" 'BEGIN { printf "%-44s %8.1f (thesis 1.0 s for its water run; goal 20)\n", "  thesis/ours", 1.0/t }'
