#!/usr/bin/env bash
# Called by bench/run.sh with the build folder: one tube-surface evaluation with
# all partials to third order (goal: under 1 microsecond).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
tube_bench=$(bench_program "$1" tube_bench)
"$tube_bench"
