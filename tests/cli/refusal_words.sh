#!/usr/bin/env bash
# Refusals that blame the right variable (issue 27, point 6): measured
# segments whose lists differ in length name the list with the extra
# values; a segment ending before its start and places out of order are
# refused where they were given (the CSV file's line and the input's
# variable naming the file, or the list's element); a rider start that
# cannot be taken (v0 = 0: the pelvis on the tube's edge) is refused as bad
# input (exit 1, nothing written) by ride and by identify_rider alike,
# naming &rider and the start's variables.
slidesim=$1
repo=$(pwd)   # tests run from the repository root
. "$(dirname "$0")/support/checks.sh"
refused() {   # name, expected message part (a grep pattern), then slidesim's options and input
  name=$1; expected=$2; shift 2
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$@" >"$name.out" 2>"$name.err"); got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1 ($(cat "$work/$name.err"))"
  check 'grep -q -- "$expected" "$work/$name.err"' "$name: the message lacks '$expected': $(cat "$work/$name.err")"
  check '! ls "$work/$name".h5* >/dev/null 2>&1' "$name: a result file was written"
}

"$slidesim" --default-input identify_rider >"$work/rider.nml"
"$slidesim" --default-input identify_water >"$work/water.nml"
grep -q '^  segment_start = 3.0, 6.5 ' "$work/rider.nml" && grep -q '^  segment_end = 5.0, 8.5 ' "$work/rider.nml" || \
  { echo "FAIL the identify_rider template's segments changed"; exit 1; }
variant() {   # name, template, sed expression: a changed copy of the template
  sed -e "$3" "$work/$2.nml" >"$work/$1.nml"
}
# list lengths: the twin template has segment_start = 3.0, 6.5 and segment_end = 5.0, 8.5
variant start_extra rider 's/^  segment_start = 3.0, 6.5 /  segment_start = 3.0, 6.5, 7.0 /'
refused start_extra "start_extra.nml:[0-9]*: &identify: segment_start = 3.0, 6.5, 7.0 is not allowed: 3 values where segment_end has 2" \
  --check start_extra.nml
variant end_extra rider 's/^  segment_end = 5.0, 8.5 /  segment_end = 5.0, 8.5, 9.0 /'
refused end_extra "end_extra.nml:[0-9]*: &identify: segment_end = 5.0, 8.5, 9.0 is not allowed: 3 values where segment_start has 2" \
  --check end_extra.nml
# the water template without its twin: three lists, the odd one out is blamed
sed -i -e 's/^ *twin_f *=.*//' \
  -e 's/^  segment_end = \(.*\)/  segment_end = \1\n  segment_speed = 2.0, 3.0, 4.0\n  section_v = 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 1.5/' "$work/water.nml"
(cd "$work" && "$slidesim" -q --check water.nml >water.out 2>water.err); got=$?
check '[ $got = 0 ]' "the water template with measured values: exit status $got ($(cat "$work/water.err"))"
variant speed_short water 's/^  segment_speed = 2.0, 3.0, 4.0/  segment_speed = 2.0, 3.0/'
refused speed_short "speed_short.nml:[0-9]*: &identify: segment_speed = 2.0, 3.0 is not allowed: 2 values where segment_start and segment_end have 3" \
  --check speed_short.nml
variant start_long water 's/^  segment_start = 10.0, 30.0, 50.0/  segment_start = 10.0, 30.0, 50.0, 55.0/'
refused start_long "start_long.nml:[0-9]*: &identify: segment_start = 10.0, 30.0, 50.0, 55.0 is not allowed: 4 values where segment_end and segment_speed have 3" \
  --check start_long.nml

# order: in the input's lists, the element named
variant backwards rider 's/^  segment_end = 5.0, 8.5 /  segment_end = 5.0, 6.0 /'
refused backwards "backwards.nml:[0-9]*: &identify: segment_end(2) = 6.0 is not allowed: segment 2 must end after its start 6.5 m" \
  --check backwards.nml
variant stations rider 's/^  station_arc_length = 2.5, 4.375, 6.25,/  station_arc_length = 2.5, 4.375, 4.0,/'
refused stations "stations.nml:[0-9]*: &identify: station_arc_length(3) = 4.0 is not allowed: station 3 must lie after the one before it (4.375 m)" \
  --check stations.nml
variant sections water 's/^  section_arc_length = 5.0, 10.0,/  section_arc_length = 5.0, 5.0,/'
refused sections "sections.nml:[0-9]*: &identify: section_arc_length(2) = 5.0 is not allowed: section 2 must lie after the one before it (5.0 m)" \
  --check sections.nml
# in a CSV file: its line, and the input's variable that names the file
cp "$repo/inputs/design/identify_rider_demo.nml" "$repo/inputs/design/rider_stations.csv" "$work/"
sed -i "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" "$work/identify_rider_demo.nml"
printf '# start, end, speed\nstart_m,end_m,speed_m_s\n3.0,5.0,3.1\n9.0,8.0,4.0\n' >"$work/rider_segments.csv"
refused csv_backwards "rider_segments.csv:4: 8.0* is not allowed: segment 2 must end after its start 9.0.* (the file named by .*identify_rider_demo.nml:[0-9]*: &identify segments_file)" \
  --check identify_rider_demo.nml

# the start: v0 = 0 (the tube's edge) is bad input for ride and identify_rider alike
sed -e "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" "$repo/inputs/ride/demo_slide.nml" >"$work/ride.nml"
sed -i 's/^  u0 = 0.5, v0 = 1.5707963267948966,/  u0 = 0.5, v0 = 0.0,/' "$work/ride.nml"
sed -i 's/^  v0 = 1.5707963267948966 /  v0 = 0.0 /' "$work/rider.nml"   # the template: one variable a line
refused ride_v0 "ride.nml:[0-9]*: &rider: the start u0 = 0.5, v0 = 0, heading0_deg = 0, speed0 = 1 (height = 1.78 m): " ride.nml
refused identify_v0 "rider.nml:[0-9]*: &rider: the start u0 = 0.5, v0 = 0, heading0_deg = 0, speed0 = 1 (height = 1.78 m): " rider.nml
refused identify_v0_check "rider.nml:[0-9]*: &rider: the start u0 = 0.5, v0 = 0" --check rider.nml
# the same words (the lines differ, and the force at the start by the rides' tolerances: ~1e-11 N)
same() { sed -e "s/^error: [^:]*:[0-9]*: //" -e "s/normal force [-0-9.E+]* N/normal force N/" "$work/$1.err"; }
check 'diff <(same ride_v0) <(same identify_v0) >/dev/null' \
  "ride and identify_rider say different things about v0 = 0: $(cat "$work/ride_v0.err" "$work/identify_v0.err")"

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
