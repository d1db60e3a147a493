#!/usr/bin/env bash
# The slide a run rides is the one the input describes, and the summary says
# which (issue 27, point 1): an input with &slide_elements and &cross_section
# but no &surface is refused (it ran on the default 50 m tube of &channel,
# exit 0), naming the group, its line and what is missing; with &surface
# kind = 'slide' it runs on that slide, and the water and ride summaries name
# the slide, its file and its centreline length. A geometry file that is
# another scenario's input (its &run says so) is refused. The group injection
# of every scenario is in tests/cli/group_injection.py (run by mutation.sh).
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

elements="&slide_elements
  n_elements = 2, kind = 'straight', 'runout'
  length = 80.0, 7.0, slope_deg = 10.0, 1.0
/
&cross_section radius = 0.5 /"
# the issue's input: the slide given, the &surface that selects it missing
printf "&run scenario = 'water', output = 'no_surface.h5' /\n&water flow_rate = 0.004 /\n%s\n" "$elements" \
  > "$work/no_surface.nml"
run_case no_surface 1 'no_surface.nml:3: &slide_elements is read only through &surface kind' \
  'this input has no &surface' "add &surface kind = 'slide'"
# the same in a ride
printf "&run scenario = 'ride', output = 'ride_no_surface.h5' /\n&rider /\n%s\n" "$elements" \
  > "$work/ride_no_surface.nml"
run_case ride_no_surface 1 'ride_no_surface.nml:3: &slide_elements is read only through &surface'
# with &surface the water runs on the slide of the input: straight 80 m and
# run-out 7 m, plus the transitions between them (2 m each by default): 87 to
# 90 m of centreline, not the 50 m tube
printf "&run scenario = 'water', output = 'with_surface.h5' /\n&surface kind = 'slide' /\n&water flow_rate = 0.004 /\n%s\n" \
  "$elements" > "$work/with_surface.nml"
run_case with_surface 0
grep -q "slide  *slide of standard elements (&slide_elements) from with_surface.nml" "$work/with_surface.out" || \
  fail "with_surface: the summary does not name the slide: $(head -c 300 "$work/with_surface.out")"
length=$(sed -n 's/^  slide centreline length *\([0-9.]*\) m$/\1/p' "$work/with_surface.out")
awk -v l="${length:-0}" 'BEGIN { exit !(l > 87 && l < 90) }' || \
  fail "with_surface: slide centreline length '$length', not the 87-90 m slide of the input"
# the ride report names the slide and its file
sed -e "s|'../demo_slide/slide.nml'|'$root/inputs/demo_slide/slide.nml'|" -e "s|output = .*|output = 'ride.h5'|" \
  "$root/inputs/ride/demo_slide.nml" > "$work/ride.nml"
extra_args="--set solver%duration=0.2"
run_case ride 0
extra_args=""
grep -q "slide  *slide of standard elements (&slide_elements) from $root/inputs/demo_slide/slide.nml" \
  "$work/ride.out" || fail "ride: the report does not name the slide: $(head -c 300 "$work/ride.out")"
grep -q "slide centreline length *66.98" "$work/ride.out" || fail "ride: the report lacks the slide's length"
# a geometry file that is a water input
sed -e "s|'../demo_slide/slide.nml'|'with_surface.nml'|" -e "s|output = .*|output = 'water_as_geometry.h5'|" \
  "$root/inputs/water/demo_slide.nml" > "$work/water_as_geometry.nml"
printf "&run scenario = 'water' /\n%s\n" "$elements" > "$work/water_geometry.nml"
sed -i -e "s|'with_surface.nml'|'water_geometry.nml'|" "$work/water_as_geometry.nml"
run_case water_as_geometry 1 "water_geometry.nml:1: &run: scenario = 'water'" 'this is an input of another scenario'

finish
