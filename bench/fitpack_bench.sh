#!/usr/bin/env bash
# Called by bench/run.sh with the build folder: our FITPACK next to scipy's
# (Debian's python3-scipy 1.10.1, the genuine Fortran) on the same data.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
fitpack_curves_bench=$(bench_program "$1" fitpack_curves_bench)
/usr/bin/python3 "$root/bench/fitpack_curves_bench.py" "$fitpack_curves_bench"
fitpack_surfaces_bench=$(bench_program "$1" fitpack_surfaces_bench)
/usr/bin/python3 "$root/bench/fitpack_surfaces_bench.py" "$fitpack_surfaces_bench"
