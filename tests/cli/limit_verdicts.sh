#!/usr/bin/env bash
# Verdicts that gate (issue 27, point 5): a ride over a limit exits 0 unless
# asked; --fail-on-limit or &evaluation fail_on_limit makes it exit status 4
# with the result file complete; asked with no limit to judge (or for a
# scenario without ride limits) the run is refused (exit 1). The report
# lists the quantities left without a limit instead of counting "0 of 3" as
# if all were checked. A sweep counts its failed rides: in the summary and
# the file (/sweep rides_failed) when some fail, exit status 2 and an
# incomplete file when all do; asked to fail on a limit, a sweep with any
# ride over one exits 4.
slidesim=$1
repo=$(pwd)   # tests run from the repository root
. "$(dirname "$0")/support/checks.sh"
status_of() { h5dump -a /status "$work/$1" 2>/dev/null | grep -o '"[a-z]*"' | tail -n 1; }

# the demo ride, 2.5 s long (the speed limit 8 m/s holds, 2 m/s does not)
sed -e "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" \
    -e "s|  output_step = 0.01|  output_step = 0.01, duration = 2.5|" "$repo/inputs/ride/demo_slide.nml" >"$work/ride.nml"
grep -q 'duration = 2.5' "$work/ride.nml" || { echo "FAIL the ride input was not shortened"; exit 1; }
run() {   # name, then slidesim's options and input
  name=$1; shift
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$@" >"$name.out" 2>"$name.err"); got=$?
}
slow='--set rider%limit_max=10.0,2.0,0.25'

# without asking: exit 0 whatever the verdict, the limits not set listed
run plain ride.nml
check '[ $got = 0 ]' "plain: exit status $got ($(cat "$work/plain.err"))"
check 'grep -q "^  no limit set for  *acceleration_longitudinal, acceleration_lateral, acceleration_normal, normal_force, wall_angle, wall_distance, ejection$" "$work/plain.out"' \
  "plain: the report does not list the limits not set: $(grep limit "$work/plain.out")"
check 'grep -q "^  limits exceeded  *0 of the 3 set$" "$work/plain.out"' "plain: the count of limits: $(grep 'limits exceeded' "$work/plain.out")"
run over ride.nml $slow
check '[ $got = 0 ]' "over a limit, not asked: exit status $got"
check 'grep -q "LIMIT EXCEEDED: speed" "$work/over.out"' "over a limit, not asked: the report says so"

# asked: exit 4, the file complete, the limit named on standard error
run gate_cli ride.nml --fail-on-limit $slow
check '[ $got = 4 ]' "--fail-on-limit, over: exit status $got, expected 4 ($(cat "$work/gate_cli.err"))"
check '[ "$(status_of gate_cli.h5)" = "\"complete\"" ]' "--fail-on-limit, over: the file is not complete: $(status_of gate_cli.h5)"
check 'grep -q "limits exceeded: 2 speed.*exit status 4" "$work/gate_cli.err"' "--fail-on-limit: the message: $(cat "$work/gate_cli.err")"
check 'grep -q "LIMIT EXCEEDED: speed" "$work/gate_cli.out"' "--fail-on-limit: the report is printed"
run gate_ok ride.nml --fail-on-limit
check '[ $got = 0 ]' "--fail-on-limit, within the limits: exit status $got ($(cat "$work/gate_ok.err"))"
sed 's|^&rider|\&evaluation\n  fail_on_limit = .true.\n/\n\&rider|' "$work/ride.nml" >"$work/gate_nml.nml"
run gate_nml gate_nml.nml $slow
check '[ $got = 4 ]' "&evaluation fail_on_limit, over: exit status $got, expected 4 ($(cat "$work/gate_nml.err"))"
check '[ "$(status_of gate_nml.h5)" = "\"complete\"" ]' "&evaluation fail_on_limit: the file is not complete"
run gate_nml_ok gate_nml.nml
check '[ $got = 0 ]' "&evaluation fail_on_limit, within the limits: exit status $got ($(cat "$work/gate_nml_ok.err"))"

# asked with nothing to judge: refused before any work
sed -e '/limit_quantity/d' -e '/limit_max/d' -e '/limit_unit/d' "$work/gate_nml.nml" >"$work/no_limits.nml"
run no_limits no_limits.nml
check '[ $got = 1 ]' "fail_on_limit without limits: exit status $got, expected 1"
check 'grep -q "no_limits.nml:[0-9]*: &evaluation: fail_on_limit = .true. is not allowed: there is no limit" "$work/no_limits.err"' \
  "fail_on_limit without limits: the message: $(cat "$work/no_limits.err")"
check '! ls "$work"/no_limits.h5* >/dev/null 2>&1' "fail_on_limit without limits: a file was written"
run water_gate "$repo/inputs/water/demo_slide.nml" --fail-on-limit
check '[ $got = 1 ]' "--fail-on-limit for water: exit status $got, expected 1"
check 'grep -q -- "--fail-on-limit: scenario water judges no ride limits" "$work/water_gate.err"' \
  "--fail-on-limit for water: the message: $(cat "$work/water_gate.err")"

# a sweep: some rides fail (the heels beyond the end at u0 = 66.5)
sed -e "s|scenario = 'ride'|scenario = 'sweep'|" "$work/ride.nml" >"$work/sweep_base.nml"
{ cat "$work/sweep_base.nml"; printf "&sweep\n  mass = 90.0, 55.0\n  u0 = 0.5, 66.5\n/\n"; } >"$work/some.nml"
run some some.nml
check '[ $got = 0 ]' "sweep, some rides failed: exit status $got ($(cat "$work/some.err"))"
check '[ "$(status_of some.h5)" = "\"complete\"" ]' "sweep, some failed: the file is not complete"
check 'h5dump -a /sweep/rides_failed "$work/some.h5" | grep -q "(0): 2"' "sweep, some failed: /sweep rides_failed is not 2"
check 'grep -q "^    failed  *2" "$work/some.out"' "sweep, some failed: the summary count"
check 'grep -q "^  rides over a limit  *0 of the 2 that ran, 3 limits set" "$work/some.out"' \
  "sweep: the rides over a limit: $(grep 'over a limit' "$work/some.out")"
check 'grep -q "^  no limit set for  *acceleration_longitudinal" "$work/some.out"' "sweep: the limits not set"
run some_gate some.nml --fail-on-limit $slow
check '[ $got = 4 ]' "sweep --fail-on-limit, rides over: exit status $got, expected 4 ($(cat "$work/some_gate.err"))"
check 'grep -q "limits exceeded: 2 speed (in 2 rides)" "$work/some_gate.err"' "sweep --fail-on-limit: the message: $(cat "$work/some_gate.err")"
check '[ "$(status_of some_gate.h5)" = "\"complete\"" ]' "sweep --fail-on-limit: the file is not complete"
run some_ok some.nml --fail-on-limit
check '[ $got = 0 ]' "sweep --fail-on-limit, within the limits: exit status $got ($(cat "$work/some_ok.err"))"
# every ride fails: exit 2, the file kept and incomplete
{ cat "$work/sweep_base.nml"; printf "&sweep\n  mass = 90.0, 55.0\n  u0 = 66.5\n/\n"; } >"$work/all.nml"
run all all.nml
check '[ $got = 2 ]' "sweep, every ride failed: exit status $got, expected 2 ($(cat "$work/all.err"))"
check '[ "$(status_of all.h5)" = "\"incomplete\"" ]' "sweep, every ride failed: the file is not incomplete: $(status_of all.h5)"
check 'grep -q "every ride failed (2 of 2; ride 1: at the start the heels cannot reach" "$work/all.err"' \
  "sweep, every ride failed: the message: $(cat "$work/all.err")"
check 'h5dump -a /sweep/rides_failed "$work/all.h5" | grep -q "(0): 2"' "sweep, every ride failed: rides_failed"
check '[ "$(wc -l <"$work/all.csv")" = 3 ] && grep -q "^  CSV summary  *all.csv$" "$work/all.out"' \
  "sweep, every ride failed: the CSV (a header and 2 rides) and its line in the summary: $(tail -n 3 "$work/all.out")"

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
