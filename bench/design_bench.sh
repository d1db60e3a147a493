#!/usr/bin/env bash
# The design loop against the thesis's CPU times (run by bench/run.sh with
# the build folder as $1; run from the repository root): the water-friction
# identification and the optimisation of table 4.12 in 1 and 2 threads
# (bench/design_bench.f90).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
build=${1:?usage: design_bench.sh BUILD_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
design_bench=$(bench_program "$build" design_bench)
"$design_bench"
