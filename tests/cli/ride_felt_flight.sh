#!/usr/bin/env bash
# What the ride report takes as felt in flight (issue 25; docs/rider.md "What
# the felt figures cover"), on the shipped jump (inputs/ride/jump.nml: the
# heels lift at 6.88 m, the back, then the pelvis at 7.84 m; the whole rider
# flies to 10.73 m and lands heels, pelvis, back):
# - every felt extreme and the largest lever arm of /evaluation lies where
#   the file's /rider/airborne says it is judged (the pelvis and another
#   contact on the slide: 0, 2, 4) or is the whole rider's free fall (7) at
#   exactly 0 g; never where the pelvis is in the air with another contact
#   on or alone on the slide (on 2572e9e: "felt braking max 2.67 g at
#   8.03 m" and "felt normal min -0.96 g at 7.84 m", inside the flight);
# - each is the judged records' extreme (0 g in the air), located between
#   the records: at least as far out, and within 1e-3 g (the records are
#   0.002 s apart; found 1.3e-4 g);
# - the time not judged is the records' (airborne 1, 3, 5, 6), in the file,
#   the JSON and the printed report;
# - the limits judge the same: braking <= 1 g and lever arm <= 0.25 m pass
#   (on 2572e9e both failed inside the flight: 2.67 g, 20 m), normal >= 0.2 g
#   fails where the free fall begins (0 g at 7.84 m);
# - a straight slide's wall climbs print as 0 (rounding noise below the
#   closure's 1e-10 m; on 2572e9e "5.0889E-14 deg").
slidesim=$1
. "$(dirname "$0")/support/checks.sh"

ride_with_limits inputs/ride/jump.nml "'airtime','drop_height','acceleration_longitudinal','lever_arm','acceleration_normal'" \
  "'s','m','g','m','g'" "0,0,-1,0,0.2" "0.6,0.2,10,0.25,10"
check 'grep -q "limit acceleration_longitudinal .*: ok" "$work/jump.out"' \
  "braking limit: $(grep acceleration_longitudinal "$work/jump.out")"
check 'grep -q "limit lever_arm .*: ok" "$work/jump.out"' "lever arm limit: $(grep -i 'limit.*lever_arm' "$work/jump.out")"
check 'grep -q "LIMIT EXCEEDED: acceleration_normal >= 0.2 g .*; worst 0 [a-z]* at arc length 7.844" "$work/jump.out"' \
  "normal limit: $(grep acceleration_normal "$work/jump.out")"
check 'grep -q "felt normal min  *0 g, weightless" "$work/jump.out"' "normal min: $(grep 'felt normal min' "$work/jump.out")"
check 'grep -q "felt g not judged  *0.0174.. s with the pelvis in the air or alone on the slide" "$work/jump.out"' \
  "time not judged: $(grep 'not judged' "$work/jump.out")"
check '[ $(grep -c "steepest on the wall *0 deg from the bottom$" "$work/jump.out") = 3 ]' \
  "wall climbs on the straight: $(grep 'steepest on the wall' "$work/jump.out")"
check '[ $(grep -c "highest on the wall *0 m along the wall from the bottom$" "$work/jump.out") = 3 ]' \
  "wall climbs on the straight: $(grep 'highest on the wall' "$work/jump.out")"
"$py" - "$work/jump.h5" "$work/jump.json" >"$work/check.out" 2>&1 <<'EOF'
import sys, json
import h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
j = json.load(open(sys.argv[2]))['values']
r, e = f['rider'], f['evaluation']
t, s, a = r['time'][:], r['arc_length'][:], r['airborne'][:]
felt = r['acceleration_g'][:].copy()
judged = np.isin(a, [0, 2, 4, 7])
felt[a == 7] = 0                                   # a free body feels nothing
bad = []
# the flight is there: heels, back, pelvis open, the whole rider in the air
if not (set(a) >= {0, 2, 6, 7} and judged.sum() > 1000):
    bad.append(f"unexpected flight: open contacts {sorted(set(a))}")


def where_judged(at, value):
    """At arc length `at`: a judged record there (the extreme is a record's or between two judged ones)."""
    near = np.nonzero(np.abs(s - at) <= 1e-9)[0]
    if len(near):
        return any(judged[i] and (a[i] != 7 or value == 0) for i in near)
    i = np.searchsorted(s, at) - 1          # between records i and i + 1: the stretch of record i
    return judged[i] and (a[i] != 7 or value == 0)


for k, axis in enumerate(('longitudinal', 'lateral', 'normal')):
    for end, pick in (('max', np.max), ('min', np.min)):
        value = e[f'acceleration_{axis}_{end}'][()]
        at = e[f'acceleration_{axis}_{end}_arc_length'][()]
        if not where_judged(at, value):
            bad.append(f"{axis} {end} {value} g at {at} m: where it is not judged "
                       f"(open contacts {sorted(set(a[np.abs(s - at) < 0.02]))})")
        recorded = pick(felt[judged, k])
        beyond = (value - recorded) * (1 if end == 'max' else -1)
        if not -1e-12 <= beyond <= 1e-3:
            bad.append(f"{axis} {end} {value} g: not the judged records' {recorded} g located (beyond by {beyond})")
lever, lever_at = e['lever_arm_max'][()], e['lever_arm_max_arc_length'][()]
if abs(lever) > 1e-6 or not where_judged(lever_at, 0):
    bad.append(f"lever arm {lever} m at {lever_at} m: the straight slide's is 0, in flight nothing presses")
# the braking and normal figures of 2572e9e, in flight
if e['acceleration_longitudinal_min'][()] < -1 or e['acceleration_normal_min'][()] < 0:
    bad.append(f"flight artefacts reported: braking {e['acceleration_longitudinal_min'][()]} g, "
               f"normal {e['acceleration_normal_min'][()]} g")
not_judged = np.sum(np.diff(t)[~judged[:-1]])
stored = e['flight/felt_not_judged_time'][()] if 'flight/felt_not_judged_time' in e else None
if stored is None or not (0.015 < not_judged < 0.02 and abs(stored - not_judged) <= 1e-12 * not_judged
                          and j.get('felt_not_judged_time') == stored):
    bad.append(f"time not judged: file {stored}, JSON {j.get('felt_not_judged_time')}, records {not_judged}")
if j['felt_longitudinal_min'] != e['acceleration_longitudinal_min'][()] or j['felt_normal_min'] != 0:
    bad.append(f"JSON felt: {j['felt_longitudinal_min']}, {j['felt_normal_min']}")
print('\n'.join(bad))
sys.exit(1 if bad else 0)
EOF
checked=$?
check '[ $checked = 0 ]' "the felt figures against the records: $(cat "$work/check.out")"

echo "$checks checks, $failures failed"
[ $failures = 0 ]
