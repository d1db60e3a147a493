#!/usr/bin/env bash
# Words that do not mislead (issue 27, point 6): the ride report says braking
# and pushing for the longitudinal felt acceleration (never a "max" that is
# negative), the side of the wall each contact climbed, what the sign of a
# lateral or normal felt acceleration means, where the exit speed is taken
# (the end of the slide), the inlets of its water; a closed standard input is a
# read error (exit 3) that says so, not "the input is empty".
slidesim=$1
repo=$(pwd)   # tests run from the repository root
. "$(dirname "$0")/support/checks.sh"

# the demo ride: braked all the way (f_long from -0.146 to -0.060 g), the
# highest climbs on the left wall (the helix turns left)
sed -e "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" "$repo/inputs/ride/demo_slide.nml" >"$work/ride.nml"
(cd "$work" && "$slidesim" -q -o ride.h5 --summary-json ride.json ride.nml >ride.out 2>ride.err); got=$?
check '[ $got = 0 ]' "demo ride: exit status $got ($(cat "$work/ride.err"))"
check '! grep -q "felt longitudinal" "$work/ride.out"' "the report still says felt longitudinal: $(grep 'felt longitudinal' "$work/ride.out")"
check 'grep -q "^  felt braking max  *0\.14[0-9]* g$" "$work/ride.out"' "braking max: $(grep braking "$work/ride.out")"
check 'grep -q "^  felt braking min  *0\.06[0-9]* g (braked all the way)$" "$work/ride.out"' \
  "braking min (the largest f_long is negative): $(grep braking "$work/ride.out")"
check '! grep -q "^  felt .*  *-[0-9.e]* g$" "$work/ride.out"' "a felt figure printed negative without its sense"
check 'grep -q "^  felt lateral max  *0\.0[0-9]* g, pushed to the left$" "$work/ride.out"' "lateral max: $(grep lateral "$work/ride.out")"
check 'grep -q "^  felt lateral min  *-0\.0[0-9]* g, pushed to the right$" "$work/ride.out"' "lateral min: $(grep lateral "$work/ride.out")"
for c in pelvis heels back; do
  check 'grep -q "^  $c steepest on the wall  *[0-9.]* deg from the bottom, on the left$" "$work/ride.out"' \
    "$c: the wall's side: $(grep "$c steepest" "$work/ride.out")"
  check 'grep -q "^  $c highest on the wall  *[0-9.]* m along the wall from the bottom, on the left$" "$work/ride.out"' \
    "$c: the wall's side: $(grep "$c highest" "$work/ride.out")"
done
# the exit speed is the speed where the ride leaves the slide, at the end of
# its last element (the demo's run-out), not as it enters the run-out
check 'grep -q "^  exit speed (end of the slide)  *[0-9.]* m/s$" "$work/ride.out"' \
  "exit speed: $(grep 'exit speed' "$work/ride.out")"
check '! grep -q "into the run-out" "$work/ride.out"' "the exit speed said to be into the run-out"
# the JSON keeps the signed values under their names
check 'grep -q "\"felt_longitudinal_max\": *-0\.06" "$work/ride.json" && grep -q "\"felt_longitudinal_min\": *-0\.14" "$work/ride.json"' \
  "the JSON's signed longitudinal values: $(grep -o '"felt_longitudinal_m[a-z]*": *[-0-9.e]*' "$work/ride.json")"
# the ride's water from two inlets: the report names them (it said only
# where the water stopped, as if all of it entered at the start)
{ cat "$work/ride.nml"; printf '&inlet\n  arc_length = 25.0\n  flow_rate = 0.002\n  speed = 2.0\n/\n'; } >"$work/inlet.nml"
(cd "$work" && "$slidesim" -q -o inlet.h5 --summary-json inlet.json inlet.nml >inlet.out 2>inlet.err); got=$?
check '[ $got = 0 ]' "ride with an inlet: exit status $got ($(cat "$work/inlet.err"))"
check 'grep -q "^  water  *.*; 0\.004 m^3/s at the start, 0\.006 m^3/s at the end (1 of 1 inlets joined)$" "$work/inlet.out"' \
  "ride with an inlet: the water line: $(grep '^  water ' "$work/inlet.out")"
check '! grep -q "inlets" "$work/ride.out"' "the one-inlet ride speaks of inlets: $(grep inlets "$work/ride.out")"

# standard input closed: a read error, not an empty input
(cd "$work" && "$slidesim" -q -o stdin.h5 - <&- >stdin.out 2>stdin.err); got=$?
check '[ $got = 3 ]' "closed standard input: exit status $got, expected 3 ($(cat "$work/stdin.err"))"
check 'grep -q "standard input is closed" "$work/stdin.err"' "closed standard input: the message: $(cat "$work/stdin.err")"
check '! grep -q "empty" "$work/stdin.err"' "closed standard input called empty"
# an empty standard input stays what it is (bad input, exit 1)
(cd "$work" && "$slidesim" -q -o empty.h5 - </dev/null >empty.out 2>empty.err); got=$?
check '[ $got = 1 ] && grep -q "the input is empty" "$work/empty.err"' "empty standard input: exit $got, $(cat "$work/empty.err")"

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
