#!/usr/bin/env bash
# The design scenarios (optimize) stop on bad input before any work: exit
# status 1, a message naming the file, the group, the variable, its value and
# what is allowed, and no result file. A small optimisation runs through to a
# complete result file.
set -u
slidesim=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0; checks=0

expect() {
  local name=$1 want=$2; shift 2
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$name.nml" >"$name.out" 2>"$name.err")
  local got=$?
  local ok=1
  [ "$got" = "$want" ] || { echo "FAIL $name: exit status $got, expected $want"; ok=0; }
  for needle in "$@"; do
    grep -qF -- "$needle" "$work/$name.err" || { echo "FAIL $name: message lacks '$needle'"; ok=0; }
  done
  if ls "$work"/*.h5 "$work"/*.h5.tmp >/dev/null 2>&1; then
    echo "FAIL $name: a result file was left behind"; ok=0; rm -f "$work"/*.h5 "$work"/*.h5.tmp
  fi
  if [ $ok = 0 ]; then failures=$((failures + 1)); echo "  message: $(cat "$work/$name.err")"; fi
}

mk() { printf "&run scenario = 'optimize', output = 'o.h5' /\n%s\n" "$2" > "$work/$1.nml"; }

mk bound_misses_start "&optimize lower(1) = 5.5 /"
expect bound_misses_start 1 bound_misses_start.nml '&optimize' 'lower(1), upper(1) = 5.5, 6.0' 'start value 5.0'
mk upper_below_lower "&optimize upper(3) = 4.0 /"
expect upper_below_lower 1 '&optimize' 'upper(3) = 4.0' 'must exceed lower(3)'
mk point_outside "&optimize design_point(2) = 9 /"
expect point_outside 1 '&optimize' 'design_point(2) = 9' '[0, 8]'
mk twice "&optimize design_point(2) = 2 /"
expect twice 1 '&optimize' 'design_point(2)' 'already a design variable'
mk bad_coordinate "&optimize design_coordinate(1) = 'w' /"
expect bad_coordinate 1 '&optimize' "design_coordinate(1) = 'w'" 'x y z'
mk bad_constraint "&optimize constraint = 'soft' /"
expect bad_constraint 1 '&optimize' "constraint = 'soft'" 'penalty exact none'
mk points_missing "&optimize n_points = 4 /"
expect points_missing 1 '&optimize' 'n_points = 4' 'give the points'
mk folding_tube "&optimize radius = 3.0 /"
expect folding_tube 1 '&optimize' 'the start design' 'fold'
mk negative_mass "&optimize body_mass = -90 /"
expect negative_mass 1 '&optimize' 'body_mass = -90'
mk unknown_variable "&optimize lever_arm = 0.3 /"
expect unknown_variable 1 '&optimize' 'lever_arm' 'allowed:'
mk no_angles "&optimize start_angles_deg = 95.0 /"
expect no_angles 1 '&optimize' 'start_angles_deg' '[-89, 89]'

# a small optimisation (three rides, loose tolerances) writes a complete file
checks=$((checks + 1))
mk too_few_rides "&optimize start_angles_deg = 0.0 /"
expect too_few_rides 1 '&optimize' 'start_angles_deg' 'at least 3 rides'

mk small "&optimize start_angles_deg = -20.0, 0.0, 20.0, ftol = 0.1, xtol = 0.1, constraint = 'none' /"
if (cd "$work" && "$slidesim" -q small.nml >small.out 2>small.err); then
  if ! h5dump -a /status "$work/o.h5" 2>/dev/null | grep -q '"complete"'; then
    echo "FAIL small: result file not marked complete"; failures=$((failures + 1))
  elif ! h5ls "$work/o.h5/optimize" | grep -q "^x "; then
    echo "FAIL small: no /optimize/x"; failures=$((failures + 1))
  fi
else
  echo "FAIL small: exit status $?: $(cat "$work/small.err")"; failures=$((failures + 1))
fi

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
