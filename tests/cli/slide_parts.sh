#!/usr/bin/env bash
# The slide parts of issue 26 at the command line (their physics:
# tests/geometry/test_slide_parts.f90; every shipped input in inputs/parts/
# runs and is plotted through cli_every_input and cli_plot_scripts): a bare
# surface of revolution does not answer the slide query, so a ride or a
# water run on it is refused before any work (exit 1, no file), the message
# naming the surface; a drop that is not the first element is refused, and
# so are sharp joints (transition_length = 0) that change slope or curvature,
# and bowl elements that do not fit; a bowl is a row of an element table;
# the rider and the water start inside a bowl.
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
refused() {   # NAME EXPECTED TEXT
  local name=$1 expected=$2
  printf '%s\n' "$3" >"$work/$name.nml"
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$name.nml" >"$name.out" 2>"$name.err"); local got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1 ($(cat "$work/$name.err"))"
  check 'grep -qF -- "$expected" "$work/$name.err"' "$name: message lacks '$expected': $(cat "$work/$name.err")"
  check '! ls "$work/$name".h5* >/dev/null 2>&1' "$name: a result file (or a temporary one) was written"
}
refused ride_bowl "the water needs a tube (kind = 'tube' or 'slide'), not a sphere zone" \
"&run scenario = 'ride' /
&surface kind = 'sphere_zone', radius = 3.0, latitude_min_deg = -89.0, latitude_max_deg = 0.0 /
&rider u0 = 0.5, v0 = -0.7, speed0 = 1.0 /"
refused water_cone "the water needs a tube (kind = 'tube' or 'slide'), not a cone" \
"&run scenario = 'water' /
&surface kind = 'cone', half_angle_deg = 35, z_min = 0.2, z_max = 3 /
&water flow_rate = 0.004 /"
refused drop_second "slide element 2 (drop): a drop is the trap-door start of a slide: only the first element can be a drop" \
"&run scenario = 'geometry' /
&geometry kind = 'slide' /
&slide_elements n_elements = 3, kind = 'straight', 'drop', 'straight', length = 5, 0, 5,
  slope_deg = 10, 80, 3, radius = 0, 8, 0, drop = 0, 10, 0 /"
refused drop_last "slide element 1 (drop): a drop needs an element after it" \
"&run scenario = 'geometry' /
&geometry kind = 'slide' /
&slide_elements n_elements = 1, kind = 'drop', slope_deg = 80, radius = 8, drop = 10 /"
# sharp joints where the slope or the curvature changes: the speed of what
# rides them would jump (tests/geometry/test_sharp_joints.f90)
refused sharp_joint "&slide_elements: slide elements: transition_length = 0 makes joint 1 (element 1, straight, to element 2, curve) sharp: the curvature jumps there" \
"&run scenario = 'geometry' /
&geometry kind = 'slide' /
&slide_elements n_elements = 2, transition_length = 0, kind = 'straight', 'curve', length = 5, 0,
  slope_deg = 10, 10, radius = 0, 8, angle_deg = 0, 90 /"
# a bowl element (tests/geometry/test_slide_bowl.f90): what does not fit is
# refused with the element, the value and why; a bowl_profile on another
# kind is refused
refused bowl_too_deep "slide element 2 (bowl): drop = 3.0 m reaches the bottom of the spherical bowl" \
"&run scenario = 'geometry' /
&geometry kind = 'slide' /
&slide_elements n_elements = 2, kind = 'straight', 'bowl', length = 5, 0, slope_deg = 10, 50,
  radius = 0, 6, drop = 0, 3, turns = 0, 1 /"
refused bowl_profile_elsewhere "&slide_elements: bowl_profile(1) = 'cone' is not allowed: a straight is no bowl" \
"&run scenario = 'geometry' /
&geometry kind = 'slide' /
&slide_elements n_elements = 2, kind = 'straight', 'bowl', length = 5, 0, slope_deg = 10, 50,
  radius = 0, 6, drop = 0, 2, turns = 0, 1, bowl_profile = 'cone' /"
# a bowl is a row of an element table (with its profile column): the same
# slide as from the namelist; a table bowl takes the namelist's points
printf 'kind, length, slope, radius, drop, turns, profile\nstraight, 5, 10\nbowl, 0, 35, 6, 2, 1, cone\n' \
  >"$work/bowl_rows.csv"
printf 'kind, length, slope, radius, drop, turns, profile\nstraight, 5, 10\nbowl, 0, 0, 6, 2, 1, table\n' \
  >"$work/bowl_table_rows.csv"
bowl_points="n_bowl_points = 6, bowl_rho = 1, 2, 3, 4, 5, 7, bowl_z = 0.7, 1.4, 2.1, 2.8, 3.5, 4.9"
for how in rows namelist table_rows table_namelist; do
  case $how in
    rows) given="&slide_elements elements_file = 'bowl_rows.csv' /" ;;
    namelist) given="&slide_elements n_elements = 2, kind = 'straight', 'bowl', length = 5, 0, slope_deg = 10, 35,
  radius = 0, 6, drop = 0, 2, turns = 0, 1, bowl_profile = 'sphere', 'cone' /" ;;
    table_rows) given="&slide_elements elements_file = 'bowl_table_rows.csv', $bowl_points /" ;;
    table_namelist) given="&slide_elements n_elements = 2, kind = 'straight', 'bowl', length = 5, 0,
  slope_deg = 10, 0, radius = 0, 6, drop = 0, 2, turns = 0, 1, bowl_profile = 'sphere', 'table', $bowl_points /" ;;
  esac
  printf '%s\n' "&run scenario = 'geometry', output = 'bowl_$how.h5' /" "&geometry kind = 'slide' /" "$given" \
    >"$work/bowl_$how.nml"
  (cd "$work" && "$slidesim" -q "bowl_$how.nml" >"bowl_$how.out" 2>&1); got=$?
  check '[ $got = 0 ]' "bowl from $how: exit $got: $(cat "$work/bowl_$how.out")"
done
check 'h5diff -q "$work/bowl_rows.h5" "$work/bowl_namelist.h5" /geometry/surface /geometry/surface' \
  "a bowl row of a table and the namelist's bowl differ"
check 'h5diff -q "$work/bowl_table_rows.h5" "$work/bowl_table_namelist.h5" /geometry/surface /geometry/surface' \
  "a table bowl row and the namelist's table bowl differ"
refused bowl_points_elsewhere "&slide_elements: bowl_rho = 1, 2, 3 is not allowed: only a bowl with bowl_profile = 'table' uses it" \
"&run scenario = 'geometry' /
&geometry kind = 'slide' /
&slide_elements n_elements = 2, kind = 'straight', 'bowl', length = 5, 0, slope_deg = 10, 50,
  radius = 0, 6, drop = 0, 2, turns = 0, 1, bowl_rho = 1, 2, 3 /"
refused bowl_table_short "n_bowl_points = 5 is not allowed: must be a whole number in [6, 400]" \
"&run scenario = 'geometry' /
&geometry kind = 'slide' /
&slide_elements n_elements = 2, kind = 'straight', 'bowl', length = 5, 0, slope_deg = 10, 0,
  radius = 0, 4, drop = 0, 2, turns = 0, 1, bowl_profile = 'sphere', 'table', n_bowl_points = 5,
  bowl_rho = 1, 2, 3, 4, 5, bowl_z = 0.7, 1.4, 2.1, 2.8, 3.5 /"
# the rider's and the water's start inside the bowl (20 m along the
# centerline, in its spiral): the rider's start closes and presses (--check
# builds it), the water runs from there to the end of the slide
(cd "$work" && "$slidesim" --check --set rider%u0=20 --set water%u0=20 "$root/inputs/parts/bowl.nml" \
  >bowl_check.out 2>&1); got=$?
check '[ $got = 0 ] && grep -q "input ok" "$work/bowl_check.out"' "rider start in the bowl: exit $got: $(cat "$work/bowl_check.out")"
printf "&run scenario = 'water', output = 'bowl_water.h5' /\n&surface kind = 'slide', geometry_file = '%s' /\n%s\n" \
  "$root/inputs/parts/bowl_slide.nml" \
  "&water flow_rate = 0.004, start = 'edges', u0 = 20.0, v_left0 = 1.9, v_right0 = 1.2415926535897932 /" \
  >"$work/bowl_water.nml"
(cd "$work" && "$slidesim" bowl_water.nml >bowl_water.out 2>&1); got=$?
check '[ $got = 0 ] && grep -q "stopped at *end of slide" "$work/bowl_water.out"' \
  "water start in the bowl: exit $got: $(cat "$work/bowl_water.out")"
echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
