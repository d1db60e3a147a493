#!/usr/bin/env bash
# The rider's flights in a ride (issue 25 points 1 and 4; inputs/ride/crest.nml):
# - the shipped crest ride with may_fly: exit 0, the heels lift off, then
#   the back and the pelvis: the whole rider flies, lands (heels, pelvis,
#   back) and the ride goes on to the end of the slide; the report,
#   --summary-json and /evaluation/flight give the airtime, the highest
#   point and each landing (its contact), whose drop height is
#   normal_speed^2/(2 |g|); the flight is where the file's /rider/airborne
#   (the open contacts) is not 0, the last landing where it turns 0;
# - the limits airtime and drop_height: exceeded when set below the ride's
#   (the verdict names where), exit 4 with --fail-on-limit;
# - without may_fly: the heels' lift-off ends the ride (as before), and a
#   flight limit or landing parameter is refused (exit 1, nothing written);
# - the ride plot shades the flight and marks the landing.
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
run() {   # name, then slidesim's options and input
  name=$1; shift
  (cd "$root" && "$slidesim" -o "$work/$name.h5" "$@" >"$work/$name.out" 2>"$work/$name.err"); got=$?
}

run crest --summary-json "$work/crest.json" inputs/ride/crest.nml
check '[ $got = 0 ]' "crest: exit status $got ($(cat "$work/crest.err"))"
check 'grep -q "^  landing 1 (heels) at arc length .*stayed on$" "$work/crest.out"' "crest: no landing line: $(grep -i landing "$work/crest.out")"
check 'grep -q "limit airtime <= 0.5 s: ok" "$work/crest.out"' "crest: airtime limit: $(grep airtime "$work/crest.out")"
"$py" - "$work/crest.h5" "$work/crest.json" >"$work/check.out" 2>&1 <<'EOF'
import sys, json
import h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
j = json.load(open(sys.argv[2]))['values']
fl = f['evaluation/flight']
g = 9.80665
assert fl['flights'][()] == 1 and fl['landings'][()] == 3, (fl['flights'][()], fl['landings'][()])
assert sorted(fl['landing/contact'][:]) == [1, 2, 3], fl['landing/contact'][:]
assert fl['whole_flights'][()] == 1 and 0 < fl['whole_airtime'][()] < fl['airtime'][()]
vn = fl['landing/normal_speed'][:]
assert np.allclose(fl['landing/drop_height'][:], vn**2/(2*g), rtol=1e-14), 'drop height'
assert 0.3 < fl['airtime'][()] < 0.45 and fl['airtime'][()] == fl['airtime_longest'][()]
air = f['rider/airborne'][:]
t = f['rider/time'][:]
flying = (air != 0).astype(int)
up = np.flatnonzero(np.diff(flying) == 1)
down = np.flatnonzero(np.diff(flying) == -1)
assert len(up) == 1 and len(down) == 1, (up, down)
# the switches: two records at one time each; the flight between them
assert t[up[0]] == t[up[0] + 1] and t[down[0]] == t[down[0] + 1]
assert abs((t[down[0]] - t[up[0]]) - fl['airtime'][()]) < 1e-12
assert abs(t[down[0]] - fl['landing/time'][-1]) < 1e-12
assert np.any(air == 7), 'the whole rider in the air'
assert abs(j['airtime'] - fl['airtime'][()]) < 1e-15 and abs(j['drop_height_max'] - fl['drop_height_max'][()]) < 1e-15
# the heels' normal force is zero while they fly and presses again after the landing
n = f['rider/heels/normal_force'][:]
heels_up = (air & 2) != 0
assert np.all(np.abs(n[heels_up]) < 1e-6), np.abs(n[heels_up]).max()
assert n[down[0] + 2] > 0
print('ok')
EOF
rc=$?
check '[ $rc = 0 ]' "crest: the file and JSON: $(cat "$work/check.out")"

# the plot: the flight shaded from the take-off to the last landing over the
# pelvis's arc length on the three plots over arc length, each landing as a
# dashed line there and as a diamond at its contact's arc length, labelled
# with the drop height
"$py" - "$root/python" "$work/crest.h5" >"$work/plot.out" 2>&1 <<'EOF2'
import sys
sys.path.insert(0, sys.argv[1])
import h5py, numpy as np
import matplotlib
matplotlib.use('Agg')
from slidesim.plot import figure
with h5py.File(sys.argv[2], 'r') as f:
    s = f['rider/arc_length'][:]
    air = f['rider/airborne'][:]
    contact_s = f['evaluation/flight/landing/arc_length'][:]
    drop = f['evaluation/flight/landing/drop_height'][:]
    time = f['rider/time'][:]
    landing_time = f['evaluation/flight/landing/time'][:]
take_off = s[np.flatnonzero(air)[0]]
landing = s[np.flatnonzero(np.diff((air != 0).astype(int)) == -1)[0] + 1]
landing_s = np.interp(landing_time, time, s)
fig = figure(sys.argv[2])
over_s = [ax for ax in fig.axes if ax.get_xlabel() == 'arc length (m)']
assert len(over_s) == 3, [ax.get_xlabel() for ax in fig.axes]
for ax in over_s:
    spans = [p for p in ax.patches if p.get_gid() == 'flight']
    assert len(spans) == 1, (ax.get_title(), len(spans))
    x = spans[0].get_xy()[:, 0]
    assert abs(x.min() - take_off) < 1e-12 and abs(x.max() - landing) < 1e-12, (ax.get_title(), x, take_off, landing)
    lines = [l for l in ax.lines if l.get_gid() == 'landing']
    assert len(lines) == 3 and np.allclose([l.get_xdata()[0] for l in lines], landing_s, atol=1e-9), \
        (ax.get_title(), len(lines))
    assert abs(lines[-1].get_xdata()[0] - landing) < 1e-9
slide = fig.axes[0]
marks = [l for l in slide.lines if l.get_gid() == 'landing']
assert len(marks) == 3 and np.allclose([m.get_xdata()[0] for m in marks], contact_s, atol=1e-12), \
    'the landings on the unrolled slide'
labels = [a.get_text() for a in slide.texts if a.get_gid() == 'landing']
assert labels == [f"{100 * h:.3g} cm drop" for h in drop], labels
print('ok')
EOF2
rc=$?
check '[ $rc = 0 ]' "crest: the plot's flight marks: $(cat "$work/plot.out")"

# limits set below the ride's: exceeded, exit 4 when asked
run tight inputs/ride/crest.nml --set rider%limit_max=0.1,0.01 --fail-on-limit
check '[ $got = 4 ]' "tight limits, --fail-on-limit: exit status $got, expected 4 ($(cat "$work/tight.err"))"
check 'grep -q "LIMIT EXCEEDED: airtime <= 0.1 s; worst 0.36" "$work/tight.out"' "tight limits: airtime: $(grep airtime "$work/tight.out")"
check 'grep -q "LIMIT EXCEEDED: drop_height <= 0.01 m; worst 0.03" "$work/tight.out"' "tight limits: drop_height: $(grep drop_height "$work/tight.out")"

# without may_fly: a flight limit is refused; without limits the lift-off ends the ride
run no_fly inputs/ride/crest.nml --set rider%may_fly=.false.
check '[ $got = 1 ]' "flight limits without may_fly: exit status $got, expected 1"
check 'grep -q "airtime limits a flight: it needs may_fly = .true." "$work/no_fly.err"' "flight limits without may_fly: $(cat "$work/no_fly.err")"
check '! ls "$work"/no_fly.h5* >/dev/null 2>&1' "flight limits without may_fly: a file was written"
sed -e '/may_fly/d' -e '/limit_/d' inputs/ride/crest.nml >"$work/plain.nml"
sed -i "s#'../parts/crest_slide.nml'#'$root/inputs/parts/crest_slide.nml'#" "$work/plain.nml"
run plain "$work/plain.nml"
check '[ $got = 0 ] && grep -q "ride ended  *lift-off: the normal force of the heels fell to zero" "$work/plain.out"' \
  "without may_fly: $(grep 'ride ended' "$work/plain.out") $(cat "$work/plain.err")"
check '! grep -q "^  flights" "$work/plain.out" && ! h5ls "$work/plain.h5/evaluation/flight" >/dev/null 2>&1' \
  "without may_fly: flight figures reported"
printf '%s\n' "$(sed 's/  u0 = 0.5/  landing_mu = 0.1\n  u0 = 0.5/' "$work/plain.nml")" >"$work/mu.nml"
run mu "$work/mu.nml"
check '[ $got = 1 ] && grep -q "landing_mu" "$work/mu.err"' "landing_mu without may_fly: exit $got: $(cat "$work/mu.err")"

echo "$checks checks, $failures failed"
[ $failures = 0 ]
