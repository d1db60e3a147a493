#!/usr/bin/env bash
# The design scenarios (optimize, identify_rider) stop on bad input before any work: exit
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

# identify_rider: the demo slide by name, the measurements in the group or in CSV files
ri() { printf "&run scenario = 'identify_rider', output = 'o.h5' /\n&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /\n&water flow_rate = 0.004, start = 'edges', u0 = 0.0, v_left0 = 1.92, v_right0 = 1.22 /\n%b\n" "$2" > "$work/$1.nml"; }
ri lists_differ "&identify station_arc_length = 3.0, 6.0, pelvis_angle = 0.0, heels_angle = 0.0, 0.0, back_angle = 0.0, 0.0 /"
expect lists_differ 1 '&identify' 'pelvis_angle' '1 values' 'one per station (2 stations)'
# the list whose length differs is the one named (heels_angle, not pelvis_angle)
ri heels_differ "&identify station_arc_length = 3.0, 6.0, pelvis_angle = 0.0, 0.0, heels_angle = 0.0, back_angle = 0.0, 0.0 /"
expect heels_differ 1 '&identify' 'heels_angle' '1 values' 'one per station (2 stations)'
ri file_and_list "&identify stations_file = 's.csv', station_arc_length = 3.0 /"
expect file_and_list 1 '&identify' 'station_arc_length' 'the stations come from stations_file'
ri missing_csv "&identify stations_file = 'none.csv' /"
expect missing_csv 3 '&identify: stations_file' 'none.csv'
printf "arc_length,pelvis,heels,back\n3.0,0.0,0.1,9.0\n" > "$work/bad.csv"
ri bad_csv "&identify stations_file = 'bad.csv' /"
expect bad_csv 1 'bad.csv' '9.0'
ri start_outside "&rider mu = 0.2 /\n&identify twin_mu = 0.07, station_arc_length = 3.0, 6.0 /"
expect start_outside 1 '&rider mu = 0.2' 'lower, upper = 0, 0.11'
ri beyond_end "&identify twin_mu = 0.07, station_arc_length = 3.0, 80.0 /"
expect beyond_end 1 'beyond the slide' '80'
ri twin_with_data "&identify twin_mu = 0.07, station_arc_length = 3.0, pelvis_angle = 0.1 /"
expect twin_with_data 1 '&identify' 'pelvis_angle' 'twin_mu synthesises the angles'
ri limits_given "&rider limit_quantity = 'speed', limit_max = 8.0, limit_unit = 'm/s' /\n&identify twin_mu = 0.07, station_arc_length = 3.0 /"
expect limits_given 1 '&rider' 'limit_quantity is not used by identify_rider'
ri upper_low "&identify twin_mu = 0.07, station_arc_length = 3.0, lower = 0.05, upper = 0.01 /"
expect upper_low 1 '&identify' 'upper = 0.01' 'must exceed lower'
# twin_mu and the bounds of mu_D have the range of &sweep mu, the rider's Coulomb mu (one declaration; they allowed up to 10)
ri twin_mu_high "&identify twin_mu = 5.0, station_arc_length = 3.0 /"
expect twin_mu_high 1 '&identify' 'twin_mu = 5.0' 'in [0, 2]'
ri upper_high "&identify twin_mu = 0.07, station_arc_length = 3.0, upper = 5.0 /"
expect upper_high 1 '&identify' 'upper = 5.0' 'in [0, 2]'
ri nothing "&identify weight = 0.5 /"
expect nothing 1 '&identify' 'give stations or segments'

# identify_water
wi() { printf "&run scenario = 'identify_water', output = 'o.h5' /\n&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /\n&water flow_rate = 0.004, start = 'edges', u0 = 0.0, v_left0 = 1.92, v_right0 = 1.22 /\n%b\n" "$2" > "$work/$1.nml"; }
wi w_lists_differ "&identify section_arc_length = 5.0, 10.0, section_v = 1.5 /"
expect w_lists_differ 1 '&identify' 'section_v' 'one per section (2 sections)'
# a list beside the file is refused by its own name (section_v, not section_arc_length)
wi w_file_and_v "&identify sections_file = 's.csv', section_v = 1.5 /"
expect w_file_and_v 1 '&identify' 'section_v' 'the sections come from sections_file'
wi w_none_estimated "&identify twin_f = 0.03, 0.1, 1.0, section_arc_length = 5.0, estimate = .false., .false., .false. /"
expect w_none_estimated 1 '&identify' 'estimate' 'at least one of f1, f2, f3'
wi w_bad_speed "&identify twin_f = 0.03, 0.1, 1.0, section_arc_length = 5.0, speed = 'average' /"
expect w_bad_speed 1 '&identify' "speed = 'average'" 'midpoint passage'
wi w_twin_with_values "&identify twin_f = 0.03, 0.1, 1.0, section_arc_length = 5.0, section_v = 1.5 /"
expect w_twin_with_values 1 '&identify' 'twin_f' 'no values and no files'
wi w_beyond "&identify twin_f = 0.03, 0.1, 1.0, section_arc_length = 5.0, 90.0 /"
expect w_beyond 1 'stations(2) = 90' 'must lie on the slide'
# twin_f and the bounds of f have the range of &water f1, f2, f3 (they allowed up to 1e5)
wi w_twin_high "&identify twin_f = 0.03, 2000.0, 1.0, section_arc_length = 5.0 /"
expect w_twin_high 1 '&identify' 'twin_f(2) = 2000.0' 'in [0, 1000]'
printf "&run scenario = 'identify_water', output = 'o.h5' /\n&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /\n&water flow_rate = 0.004, start = 'edges', u0 = 0.0, v_left0 = 1.92, v_right0 = 1.22, stations = 5.0 /\n&identify twin_f = 0.03, 0.1, 1.0, section_arc_length = 5.0 /\n" > "$work/w_stations.nml"
expect w_stations 1 '&water' 'stations are not used by identify_water'

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
