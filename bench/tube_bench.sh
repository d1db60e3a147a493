#!/usr/bin/env bash
# Called by bench/run.sh with the build folder: one tube-surface evaluation with
# all partials to third order (goal: under 1 microsecond).
set -euo pipefail
"$1/bench/tube_bench"
