#!/usr/bin/env bash
# The water down the demo slide vs the thesis's 1.0 s (run by bench/run.sh with
# the build folder as $1; run from the repository root).
set -euo pipefail
build=${1:?usage: water_bench.sh BUILD_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
"$build/bench/water_bench" inputs/water/demo_slide.nml
