#!/usr/bin/env bash
# Called by bench/run.sh with the build folder: the multibody core's cases.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
multibody_bench=$(bench_program "$1" multibody_bench)
"$multibody_bench"
