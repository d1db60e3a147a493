#!/usr/bin/env bash
# Runs slidesim (installing what it needs and building it first if needed).
# Without arguments it runs the built-in default input; otherwise the
# arguments go to slidesim, e.g.
#   scripts/run.sh inputs/point_mass/ellipsoid.nml
# Installs the runtime set of scripts/install-dependencies.sh: the build set
# first, then the plot set (Python for the plot scripts; the program does not
# need it) in the background while CVODE and slidesim build, so that apt's
# disk-bound unpacking overlaps the processor-bound build. One apt-get at a
# time: the build set's is done before the plot set's starts, and the CVODE
# step installs no packages then. Should the plot set's install fail, run.sh
# says so with its log's path and stops with status 1 before the ride.
# Builds only the slidesim program (SLIDESIM_PROGRAM_ONLY, scripts/build.sh: a
# new build/ is configured for the program alone, one configured before is
# used as it is); scripts/check.sh adds the rest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLIDESIM_BUILD_DIR:-$root/build}
deps=$root/scripts/install-dependencies.sh
"$deps" --build-packages

plot_missing=()
for p in $("$deps" --list plot); do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || plot_missing+=("$p")
done
plot_pid=""
if ((${#plot_missing[@]} > 0)); then
  # sudo asks for a password here, not from the background
  [ "$(id -u)" = 0 ] || ! command -v sudo >/dev/null || sudo -v
  mkdir -p "$build"
  plot_log=$build/install-plot-set.log
  echo "installing the plot set in the background (log: $plot_log): ${plot_missing[*]}"
  "$deps" --plot </dev/null >"$plot_log" 2>&1 &
  plot_pid=$!
  trap '[ -z "$plot_pid" ] || echo "the plot set is still being installed in the background (log: $plot_log)" >&2' EXIT
fi

"$deps" --build   # CVODE: the build set is installed, so no apt-get here
SLIDESIM_PROGRAM_ONLY=1 "$root/scripts/build.sh" >/dev/null

if [ -n "$plot_pid" ]; then
  status=0
  wait "$plot_pid" || status=$?
  plot_pid=""
  if [ "$status" != 0 ]; then
    echo "error: installing the plot set (${plot_missing[*]}) failed with status $status;" \
      "see $plot_log (slidesim is built; run it again once that is fixed)" >&2
    exit 1
  fi
  echo "plot set installed"
fi
trap - EXIT
exec "$build/slidesim" "$@"
