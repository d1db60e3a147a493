#!/usr/bin/env bash
# Called by bench/run.sh with the build folder: our FITPACK next to scipy's
# (Debian's python3-scipy 1.10.1, the genuine Fortran) on the same data.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
/usr/bin/python3 "$root/bench/fitpack_curves_bench.py" "$1/bench/fitpack_curves_bench"
/usr/bin/python3 "$root/bench/fitpack_surfaces_bench.py" "$1/bench/fitpack_surfaces_bench"
