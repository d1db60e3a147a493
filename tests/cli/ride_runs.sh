#!/usr/bin/env bash
# The ride scenario end to end: the default run (water, then the rider) writes
# /water, /rider and /evaluation and prints the ride report; bad rider inputs
# are refused before any work (exit status 1, no result file), each message
# naming what is wrong: a negative mass, a start where the heels cannot reach
# the slide (which contact and by how much), a drag sphere larger than the
# tube or than a flume's bottom, a limit in a unit of the wrong kind, a rider at rest where the start
# is not steeper than its friction holds. A ride that fails part way (too
# few steps allowed) prints its whole report, the results line last, before
# the error, also when both streams go to one file.
slidesim=$1
repo=$(pwd)   # tests run from the repository root
. "$(dirname "$0")/support/checks.sh"

(cd "$work" && "$slidesim" -q -o ride.h5 "$repo/inputs/ride/demo_slide.nml" >ride.out 2>ride.err); got=$?
check '[ $got = 0 ]' "demo ride: exit status $got ($(cat "$work/ride.err"))"
check 'grep -q "ride ended  *end of the slide" "$work/ride.out"' "demo ride: the report says it reached the end"
check 'grep -q "top speed" "$work/ride.out" && grep -q "felt normal max" "$work/ride.out"' "demo ride: report figures"
check 'h5dump -a /status "$work/ride.h5" | grep -q "\"complete\""' "demo ride: file complete"
for d in /water/speed /rider/time /rider/acceleration_g /rider/heels/normal_force /rider/back/in_water \
         /evaluation/top_speed /evaluation/limits/1_exit_speed/verdict; do
  check 'h5ls "$work/ride.h5$d" >/dev/null 2>&1' "demo ride: $d written"
done

# bad inputs: take the demo input and change one thing
bad() {   # name, sed expression, expected message part
  name=$1; expected=$3
  sed -e "$2" "$repo/inputs/ride/demo_slide.nml" | sed "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" \
    >"$work/$name.nml"
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$name.nml" >"$name.out" 2>"$name.err"); got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1 ($(cat "$work/$name.err"))"
  check 'grep -q -- "$expected" "$work/$name.err"' "$name: message lacks '$expected': $(cat "$work/$name.err")"
  check '! ls "$work/$name".h5* >/dev/null 2>&1' "$name: a result file (or a temporary one) was written"
}
bad negative_mass "s/mass = 68.5/mass = -68.5/" "&rider: mass = -68.5 is not allowed"
bad heels_beyond_end "s/u0 = 0.5, v0/u0 = 66.5, v0/" "the heels cannot reach the slide"
bad back_before_start "s/u0 = 0.5, v0/u0 = 0.1, v0/" "the back cannot reach the slide"
bad heels_across "s/heading0_deg = 0.0/heading0_deg = 90.0/; s/height = 1.78/height = 2.4/" "cannot reach the slide: the contact point stays"
bad sphere_too_large "s/drag_radius = 0.5, 0.05, 0.5/drag_radius = 0.6, 0.05, 0.5/" "drag_radius(1) = 0.6 is not allowed"
# at rest (speed0 = 0, a drop's trap door) only where the start is steeper than mu holds (12 deg: tan 0.21)
bad at_rest_held "s/speed0 = 1.0/speed0 = 0.0/; s/mu = 0.0724419/mu = 0.3/" "needs a start steeper than its friction holds: tan(slope) = 0.2125"
# the spheres are checked on every slide, not only a circular tube: the bowl
# slide's open U (a flume of radius 0.6 m) holds no 0.7 m sphere (before, no
# check: the ride ran)
sed -e "s/drag_radius = 0.5, 0.05, 0.5/drag_radius = 0.7, 0.05, 0.5/" "$repo/inputs/parts/bowl.nml" | \
  sed "s|'bowl_slide.nml'|'$repo/inputs/parts/bowl_slide.nml'|" >"$work/flume_sphere.nml"
(cd "$work" && "$slidesim" -q --check flume_sphere.nml >flume_sphere.out 2>flume_sphere.err); got=$?
check '[ $got = 1 ]' "flume_sphere: exit status $got, expected 1 ($(cat "$work/flume_sphere.err"))"
check 'grep -q "drag_radius(1) = 0.7 is not allowed.*must fit in the slide.* 0.6 m" "$work/flume_sphere.err"' \
  "flume_sphere: message: $(cat "$work/flume_sphere.err")"
bad limit_unit "s/limit_unit     = 'm\/s',        'm\/s',   'm'/limit_unit = 'g', 'm\/s', 'm'/" "unit 'g' does not measure exit_speed"

# failed part way, standard output and error into one file: the report's
# last line ("results (INCOMPLETE) path", with its newline) comes before the error
sed -e "s/^&solver /\&solver max_steps = 3, /" "$repo/inputs/ride/demo_slide.nml" | \
  sed "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" >"$work/few_steps.nml"
(cd "$work" && "$slidesim" -q -o few_steps.h5 few_steps.nml >few_steps.all 2>&1); got=$?
check '[ $got = 2 ]' "few steps: exit status $got, expected 2 ($(cat "$work/few_steps.all"))"
check 'tail -n 2 "$work/few_steps.all" | head -n 1 | grep -q "^  results (INCOMPLETE) *.*few_steps.h5$"' \
  "few steps: the results line is not the line before the error: $(tail -n 3 "$work/few_steps.all")"
check 'tail -n 1 "$work/few_steps.all" | grep -q "^error: ride: more than max_steps"' \
  "few steps: the error is not the last line: $(tail -n 2 "$work/few_steps.all")"

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
