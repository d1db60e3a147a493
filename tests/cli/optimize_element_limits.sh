#!/usr/bin/env bash
# A design variable's bounds against its element's own limits (docs/design.md,
# "Designs from standard parts"): on inputs/design/optimize_standard_parts.nml
# each bound that would make an element &slide_elements refuses is refused
# at input (exit 1, nothing written), the message naming the file, the group,
# the bound (indexed), its value, the element (number and kind) and the range
# that kind allows, in &slide_elements' words (its check_element, one place):
# - a straight's slope above and below [-45, 45] deg (inside the catalogue's
#   [-60, 60]: accepted before, and the run went to 40 deg and ended exit 2);
# - a curve's, a run-out's and a funnel's slope above 45 deg;
# - a curve's turning angle below 1e-6 deg (the catalogue's range is open at 0);
#   one above 720 deg is refused by the catalogue list's range (checked after
#   the element's; as before);
# - a helix's radius whose lower bound makes its drop steeper than 45 deg
#   (a limit on another of its values, named as such);
# - the start value: a straight at 50 deg is refused by &slide_elements itself
#   before the bounds are looked at (as before this check);
# - the shipped input and bounds right at a limit (+-45 deg) pass --check.
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
input=$root/inputs/design/optimize_standard_parts.nml

# refuse NAME WORDS ARGS...: refused at input (check_refused), the message naming the file
refuse() {
  local case=$1
  check_refused "$@"
  check 'grep -qE -- "(optimize_standard_parts.nml|steep.nml):[0-9]+: &|--set" "$work/$case.err"' \
    "$case: the message names neither the file's line nor the --set: $(cat "$work/$case.err")"
}
# accept NAME ARGS...: --check with ARGS ends with exit status 0
accept() {
  local name=$1 got
  shift
  (cd "$work" && "$slidesim" -q --check "$@" >"$name.out" 2>"$name.err"); got=$?
  check '[ $got = 0 ]' "$name: exit status $got, expected 0: $(cat "$work/$name.err")"
}

# last round's case in the file itself (start 44, lower 40, upper 60): the message names the file's line
sed -e 's/^\(  slope_deg *= *8.0, *6.0, *\)8.0/\144.0/' -e 's/^\(  lower *= *3.0, *3.0, *\)4.0/\140.0/' \
  -e 's/^\(  upper *= *8.0, *8.0, *\)12.0/\160.0/' "$input" >"$work/steep.nml"
line=$(grep -n '^  upper *=' "$work/steep.nml" | cut -d: -f1)
refuse straight_up "steep.nml:$line: &design_elements: upper(3) = 60.0 is not allowed: element 3 is a straight, and a straight's slope must lie in [-45, 45] (deg; only a drop is steeper) (&slide_elements): the bounds may hold only elements that can be built" \
  "$work/steep.nml"
steep_start=(--set 'slide_elements%slope_deg=8,6,44,6,8,2')
refuse straight_down "&design_elements: lower(3) = -50.0 is not allowed: element 3 is a straight, and a straight's slope must lie in [-45, 45]" \
  --set 'design_elements%lower=3,3,-50' "$input"
refuse curve_slope "upper(3) = 50.0 is not allowed: element 2 is a curve, and a curve's slope must lie in [-45, 45]" \
  --set 'design_elements%element=2,4,2' --set 'design_elements%upper=8,8,50' "$input"
refuse runout_slope "upper(3) = 46.0 is not allowed: element 6 is a runout, and a runout's slope must lie in [-45, 45]" \
  --set 'design_elements%element=2,4,6' --set 'design_elements%lower=3,3,0' --set 'design_elements%upper=8,8,46' \
  "$input"
refuse funnel_slope "upper(3) = 50.0 is not allowed: element 5 is a funnel, and a funnel's slope must lie in [-45, 45]" \
  --set "slide_elements%kind='straight','curve','straight','curve','funnel','runout'" \
  --set 'slide_elements%radius=0,4,0,4,1,0' --set 'design_elements%element=2,4,5' \
  --set 'design_elements%upper=8,8,50' "$input"
refuse curve_angle "lower(3) = 1.0E-07 is not allowed: element 2 is a curve, and a curve needs a turning angle in [1e-6, 720] (deg)" \
  --set "design_elements%parameter='radius','radius','angle'" --set 'design_elements%element=2,4,2' \
  --set 'design_elements%lower=3,3,1e-7' --set 'design_elements%upper=8,8,120' \
  --unset catalogue%slope_step_deg --set 'catalogue%angle_step_deg=15' "$input"
refuse angle_catalogue "lower(3), upper(3) = 45.0, 800.0 is not allowed: the angle must lie in (0, 720] deg (the range of &catalogue angles_deg)" \
  --set "design_elements%parameter='radius','radius','angle'" --set 'design_elements%element=2,4,2' \
  --set 'design_elements%lower=3,3,45' --set 'design_elements%upper=8,8,800' \
  --unset catalogue%slope_step_deg --set 'catalogue%angle_step_deg=15' "$input"
helix=(--set "slide_elements%kind='straight','curve','straight','helix','straight','runout'"
  --set 'slide_elements%slope_deg=8,6,8,0,8,2' --set 'slide_elements%angle_deg=0,90,0,0,0,0'
  --set 'slide_elements%turns=0,0,0,0.25,0,0' --set 'slide_elements%drop=0,0,0,4,0,0')
refuse helix_radius "lower(2) = 2.0 is not allowed: element 4 is a helix, and with radius 2 m its drop = 4.0 is refused: the helix would be steeper than 45 deg (|drop| <= 2 pi radius turns)" \
  "${helix[@]}" --set 'design_elements%lower=3,2,4' "$input"
refuse start_value "slope_deg(3) = 50.0 is not allowed: a straight's slope must lie in [-45, 45]" \
  --set 'slide_elements%slope_deg=8,6,50,6,8,2' --set 'design_elements%upper=8,8,60' "$input"
accept shipped "$input"
accept at_limits "${steep_start[@]}" --set 'design_elements%lower=3,3,-45' --set 'design_elements%upper=8,8,45' \
  "$input"
accept helix_ok "${helix[@]}" --set 'design_elements%lower=3,3,4' "$input"
echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
