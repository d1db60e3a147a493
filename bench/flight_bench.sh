#!/usr/bin/env bash
# The cost of the rider's flights (issue 25: a ride with flight phases at
# most 1.5 times the CPU of the same ride without them). The shipped crest
# and jump rides (inputs/ride/crest.nml, jump.nml) with may_fly, and the
# same rides without it (their limits unset: they need may_fly), which end
# at the heels' lift-off. Reported: the rider's CPU time (the report's
# "CPU time rider", median of 5 runs) per simulated second of the ride, and
# the with/without ratio. Run from the repository root with the build
# folder as $1 (Release).
set -euo pipefail
build=${1:?usage: flight_bench.sh BUILD_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
slidesim=$(cd "$build" && pwd)/slidesim
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root"
# median over 5 runs of (rider CPU s, ride s)
measure() {
  for i in 1 2 3 4 5; do
    "$slidesim" -o "$work/r.h5" "$@" 2>/dev/null |
      awk '/^  CPU time rider/ { cpu = $4 } /^  ride time/ { t = $3 } END { print cpu, t }'
  done | sort -g | sed -n 3p
}
printf '%-34s %10s %10s %14s\n' 'ride' 'CPU (s)' 'ride (s)' 'CPU per ride-s'
for ride in crest jump; do
  read -r cpu_fly t_fly < <(measure "inputs/ride/$ride.nml")
  read -r cpu_no t_no < <(measure "inputs/ride/$ride.nml" --set rider%may_fly=.false. \
    --unset rider%limit_quantity --unset rider%limit_max --unset rider%limit_unit)
  awk -v r="$ride" -v c1="$cpu_fly" -v t1="$t_fly" -v c0="$cpu_no" -v t0="$t_no" 'BEGIN {
    printf "%-34s %10.4f %10.4f %14.4f\n", r " with may_fly", c1, t1, c1/t1
    printf "%-34s %10.4f %10.4f %14.4f\n", r " without (ends at the lift-off)", c0, t0, c0/t0
    printf "%-34s %39.2f (goal <= 1.5)\n", "  ratio per ride-second", (c1/t1)/(c0/t0) }'
done
