#!/usr/bin/env bash
# Runs slidesim (building it first if needed). Without arguments it runs the
# built-in default input; otherwise the arguments go to slidesim, e.g.
#   scripts/run.sh inputs/point_mass/ellipsoid.nml
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/build.sh" >/dev/null
exec "${SLIDESIM_BUILD_DIR:-$root/build}/slidesim" "$@"
