#!/usr/bin/env bash
# Runs slidesim (installing what it needs and building it first if needed).
# Without arguments it runs the built-in default input; otherwise the
# arguments go to slidesim, e.g.
#   scripts/run.sh inputs/point_mass/ellipsoid.nml
# Installs only the runtime set (scripts/install-dependencies.sh --runtime)
# and builds only the slidesim program (SLIDESIM_PROGRAM_ONLY, scripts/build.sh:
# a new build/ is configured for the program alone, one configured before is
# used as it is); scripts/check.sh adds the rest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-dependencies.sh" --runtime
SLIDESIM_PROGRAM_ONLY=1 "$root/scripts/build.sh" >/dev/null
exec "${SLIDESIM_BUILD_DIR:-$root/build}/slidesim" "$@"
