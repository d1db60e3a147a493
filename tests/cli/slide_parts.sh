#!/usr/bin/env bash
# The slide parts of issue 26 at the command line (their physics:
# tests/geometry/test_slide_parts.f90; every shipped input in inputs/parts/
# runs and is plotted through cli_every_input and cli_plot_scripts): a bowl
# (a surface of revolution) does not answer the slide query, so a ride or a
# water run on it is refused before any work (exit 1, no file), the message
# naming the surface; a drop that is not the first element is refused, and
# so are sharp joints (transition_length = 0) that change slope or curvature.
set -u
slidesim=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0; checks=0
check() { checks=$((checks + 1)); if ! eval "$1"; then echo "FAIL $2"; failures=$((failures + 1)); fi; }
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
echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
