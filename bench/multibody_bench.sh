#!/usr/bin/env bash
# Called by bench/run.sh with the build folder: the multibody core's cases.
set -euo pipefail
"$1/bench/multibody_bench"
