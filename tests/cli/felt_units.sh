#!/usr/bin/env bash
# Felt accelerations say which g they are multiples of (issue 28): a ride
# under standard gravity writes units 'gravity', one under 9.81 m/s^2 writes
# '9.81 m/s^2', in /rider, /evaluation (also an acceleration limit's bounds,
# worst and excess) and the JSON summary; pint and UDUNITS-2 read both as
# |g| m/s^2 (tests/cli/check_felt_units.py). The printed report still says g.
set -u
slidesim=$1
repo=$(pwd)   # tests run from the repository root
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

# the demo ride, 1 s long, with a limit on the felt normal acceleration in g
sed -e "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" \
    -e "s|  output_step = 0.01|  output_step = 0.01, duration = 1.0|" \
    -e "s|limit_quantity = 'exit_speed', 'speed', 'lever_arm'|&, 'acceleration_normal'|" \
    -e "s|limit_max      = 10.0,         8.0,     0.25|&, 0.5|" \
    -e "s|limit_unit     = 'm/s',        'm/s',   'm'|&, 'g'|" "$repo/inputs/ride/demo_slide.nml" >"$work/ride.nml"
[ "$(grep -c "duration = 1.0\|'acceleration_normal'\|0.25, 0.5\|'m', 'g'" "$work/ride.nml")" = 4 ] \
  || { echo "FAIL the ride input was not changed as meant"; cat "$work/ride.nml"; exit 1; }
for case in standard:9.80665:gravity other:9.81:9.81_m/s^2; do
  IFS=: read -r name g units <<<"$case"
  units=${units/_/ }
  (cd "$work" && "$slidesim" -o "$name.h5" --summary-json "$name.json" --set "rider%gravity=0,0,-$g" ride.nml \
    >"$name.out" 2>"$name.err") || fail "$name: exit status $? ($(tail -3 "$work/$name.err"))"
  "$python" "$repo/tests/cli/check_felt_units.py" "$g" "$units" "$work/$name.h5" "$work/$name.json" \
    || fail "$name: the felt units"
  grep -q '^  felt normal max .* g' "$work/$name.out" || fail "$name: the report does not print g: $(grep felt "$work/$name.out")"
done
[ "$failures" = 0 ]
