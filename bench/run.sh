#!/usr/bin/env bash
# Runs the benchmarks (Release build in build/). Timings are medians of repeated
# runs; compare them as ratios, e.g. against the thesis's CPU times
# (shared/seed/README.md), not as absolute pass/fail numbers.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLIDESIM_BUILD_DIR:-$root/build}
# everything, and the benchmarks, which a Release build makes on demand only
"$root/scripts/build.sh" >/dev/null
cmake --build "$build" -j "$(nproc)" --target benchmarks >/dev/null
cd "$root"

echo "== point mass on elementary surfaces (issue: foundation) =="
point_mass_bench=$(bench_program "$build" point_mass_bench)
"$point_mass_bench" inputs/point_mass/*.nml

for extra in "$root"/bench/*_bench.sh; do
  [ -e "$extra" ] || continue
  echo "== $(basename "$extra" .sh) =="
  bash "$extra" "$build"
done
