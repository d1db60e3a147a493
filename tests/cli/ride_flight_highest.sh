#!/usr/bin/env bash
# The flights' highest point above the slide does not depend on the output
# step (issue 25 point 4; rider_extremes' gap quantities, located on the
# integrator's dense output): the shipped jump (inputs/ride/jump.nml, the
# heels rise highest, 0.215 m) at output steps 0.01 and 0.0037 s gives the
# same /evaluation/flight/highest to 1e-8 m (the rides themselves differ by
# ~2e-9 m: each record re-solves the closure in the integration's
# workspace, tolerance 1e-10 m) and the same place to 1e-6 m. Taken at the
# records (3e73489) it moved by 8.5e-4 m (0.21410 and 0.21496 m).
slidesim=$1
. "$(dirname "$0")/support/checks.sh"

for step in 0.01 0.0037; do
  (cd "$root" && "$slidesim" -o "$work/jump$step.h5" --set solver%output_step=$step inputs/ride/jump.nml \
    >"$work/jump$step.out" 2>"$work/jump$step.err"); got=$?
  check '[ $got = 0 ]' "jump at output step $step: exit status $got ($(cat "$work/jump$step.err"))"
done
"$py" - "$work/jump0.01.h5" "$work/jump0.0037.h5" >"$work/check.out" 2>&1 <<'PY'
import sys
import h5py
a, b = (h5py.File(name, 'r')['evaluation/flight'] for name in sys.argv[1:3])
ha, hb = a['highest'][()], b['highest'][()]
assert a['highest_contact'][()] == b['highest_contact'][()] == 2, 'the heels rise highest'
assert 0.2 < ha < 0.23, ha
assert abs(ha - hb) <= 1e-8, f'highest {ha!r} at output step 0.01 s, {hb!r} at 0.0037 s'
assert abs(a['highest_arc_length'][()] - b['highest_arc_length'][()]) <= 1e-6, 'the same place'
print('ok')
PY
rc=$?
check '[ $rc = 0 ]' "the highest point: $(cat "$work/check.out")"

echo "ride_flight_highest: $checks checks, $failures failed"
[ $failures = 0 ]
