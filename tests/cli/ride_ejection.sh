#!/usr/bin/env bash
# Over the top of an open section's wall (issue 25, point 4: ejection). A body
# point whose surface joint reaches the side edge v of a flume's wall leaves
# the slide there: a physical result the model cannot follow, not a failure
# of the computation. Before, it was a failure (exit 2, "reached the edge v").
# - a frictionless point mass thrown across a straight flume goes over the
#   wall top: exit 0, complete file, outcome 'over the side edge', the last
#   record at the edge, energy conserved to the end (closed form: no work);
# - a rider too fast for a tight curve of a flume: exit 0, outcome 'ejected:
#   the <contact> went over the top of the <side> wall', the summary's
#   EJECTED line, /rider attribute `ejected`, /evaluation/ejected_arc_length
#   equal to the pelvis's last arc length; the wall's side agrees with the
#   contact's recorded wall angle (+: left);
#   its plot (slidesim.plot, scripts/plot_ride.py) marks the ejection: a
#   line at that arc length, a cross where the contact left the slide;
# - the limit `ejection` (max 0, unit '1') is exceeded, and exits 4 when asked;
#   a unit that does not count is refused (exit 1, nothing written);
# - the same rider slower stays in the flume (no ejection, limit ok, no mark).
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
status_of() { h5dump -a /status "$work/$1" 2>/dev/null | grep -o '"[a-z]*"' | tail -n 1; }
run() {   # name, then slidesim's options and input
  name=$1; shift
  (cd "$work" && "$slidesim" -o "$name.h5" "$@" >"$name.out" 2>"$name.err"); got=$?
}

# a flume (radius 0.52 m, walls 0.164 m) along a 20 degree straight, a tight
# 3 m left curve and a straight
cat >"$work/flume.nml" <<'EOF'
&geometry
  kind = 'slide'
/
&slide_elements
  n_elements = 3
  kind = 'straight', 'curve', 'straight'
  length = 5.0, 0.0, 5.0
  slope_deg = 20.0, 10.0, 8.0
  radius = 0.0, 3.0, 0.0
  angle_deg = 0.0, 90.0, 0.0
  direction = 'left', 'left', 'left'
/
&cross_section
  kind = 'flume', radius = 0.52, wall = 0.164, joint_width_deg = 2.8648
/
EOF

# 1. the point mass thrown across the first straight at 10 rad/s (5.2 m/s
#    across; the wall top is 0.684 m above the bottom: it needs 3.7 m/s)
cat >"$work/mass.nml" <<'EOF'
&run
  scenario = 'point_mass'
/
&solver
  method = 'adams', rtol = 1e-12, atol = 1e-12
  duration = 3.0, output_step = 0.01
/
&surface
  kind = 'slide', geometry_file = 'flume.nml'
/
&point_mass
  u0 = 0.5, v0 = 1.5707963267948966, du0 = 0.5, dv0 = 10.0
  friction = 'none'
/
EOF
run mass mass.nml
check '[ $got = 0 ]' "point mass over the wall: exit status $got, expected 0 ($(cat "$work/mass.err"))"
check '[ "$(status_of mass.h5)" = "\"complete\"" ]' "point mass over the wall: the file is not complete"
"$py" - "$work/mass.h5" >"$work/mass.py.out" 2>&1 <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
g = f['point_mass']
# the point mass's stop is in the file's status_message ('ok: <where it stopped>')
outcome = f.attrs['status_message']
outcome = outcome.decode() if isinstance(outcome, bytes) else outcome
assert outcome.startswith('ok: over the side edge: '), outcome
v = g['v'][:]
# the flume's v runs over [-w/R, pi + w/R] (the walls by their length over
# the radius); the event sits 1e-7 of the domain inside the edge
edge = np.pi + 0.164/0.52
assert abs(v[-1] - edge) < 1e-6*(np.pi + 2*0.164/0.52), (v[-1], edge)
assert np.all(v[:-1] < v[-1] + 1e-12), 'v went beyond the last record'
e = g['kinetic_energy'][:] + g['potential_energy'][:]
assert abs(e[-1] - e[0]) <= 1e-8*abs(g['kinetic_energy'][0]), (e[0], e[-1])
print('ok', outcome)
EOF
mass_rc=$?   # (not `$?` inside check: its message's substitutions reset it)
check '[ $mass_rc = 0 ]' "point mass over the wall: $(cat "$work/mass.py.out")"

# 2. the rider at 6 m/s into the tight curve
cat >"$work/ride.nml" <<'EOF'
&run
  scenario = 'ride'
/
&surface
  kind = 'slide', geometry_file = 'flume.nml'
/
&water
  flow_rate = 0.004
  start = 'edges', u0 = 0.0, v_left0 = 1.9207963267948966, v_right0 = 1.2207963267948966
/
&rider
  sex = 'male', mass = 68.5, height = 1.78, com_height = 0.075
  mu = 0.02
  u0 = 0.5, v0 = 1.5707963267948966, heading0_deg = 0.0, speed0 = 6.0
  limit_quantity = 'ejection', limit_max = 0, limit_unit = '1'
/
EOF
run ride ride.nml
check '[ $got = 0 ]' "ejected rider: exit status $got, expected 0 ($(cat "$work/ride.err"))"
check '[ "$(status_of ride.h5)" = "\"complete\"" ]' "ejected rider: the file is not complete"
check 'grep -q "^  ride ended  *ejected: the [a-z]* went over the top of the \(left\|right\) wall of the open section at arc length" "$work/ride.out"' \
  "ejected rider: the outcome line: $(grep 'ride ended' "$work/ride.out")"
check 'grep -q "^  EJECTED  *the [a-z]* went over the top of a wall" "$work/ride.out"' "ejected rider: no EJECTED line"
check 'grep -q "LIMIT EXCEEDED: ejection" "$work/ride.out"' "ejected rider: the ejection limit is not exceeded: $(grep ejection "$work/ride.out")"
"$py" - "$work/ride.h5" >"$work/ride.py.out" 2>&1 <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
r = f['rider']
text = lambda a: a.decode() if isinstance(a, bytes) else a
outcome = text(r.attrs['outcome'])
who = text(r.attrs['ejected'])
assert outcome.startswith('ejected: the ' + who + ' went over the top of the '), (outcome, who)
side = 'left' if 'of the left wall' in outcome else 'right'
angle = r[who]['wall_angle'][-1]
# the flume's walls are vertical above the half circle: the contact leaves
# over the top of a wall on its vertical part, wall angle +-pi/2 (left +)
assert (angle > 0) == (side == 'left') and abs(abs(angle) - np.pi/2) < 1e-9, (side, angle)
at = f['evaluation/ejected_arc_length'][()]
assert at == r['arc_length'][-1], (at, r['arc_length'][-1])
assert r.attrs['reached_end'] == 0
print('ok', who, side, at)
EOF
ride_rc=$?
check '[ $ride_rc = 0 ]' "ejected rider, the file: $(cat "$work/ride.py.out")"

# the plot's ejection marks (none for a ride that was not ejected)
plot_marks() {   # result file: prints the marks' x (arc length) and points
  DISPLAY= "$py" - "$root/python" "$work/$1" <<'EOF'
import sys
sys.path.insert(0, sys.argv[1])
import matplotlib
matplotlib.use('Agg')
from slidesim.plot import figure
fig = figure(sys.argv[2])
lines = [a for ax in fig.axes for a in ax.lines if a.get_gid() == 'ejection']
for a in lines:
    data = a.get_data_3d() if hasattr(a, 'get_data_3d') else a.get_data()
    print(a.get_linestyle(), *(f'{float(v[0]):.9f}' for v in data), sep='|')
EOF
}
plot_marks ride.h5 >"$work/ride.marks" 2>&1
"$py" - "$work/ride.h5" "$work/ride.marks" >"$work/marks.py.out" 2>&1 <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
who = f['rider'].attrs['ejected']
who = who.decode() if isinstance(who, bytes) else who
at = f['evaluation/ejected_arc_length'][()]
marks = [line.strip().split('|') for line in open(sys.argv[2])]
lines = [float(m[1]) for m in marks if m[0] == '-.']
crosses = [[float(v) for v in m[1:]] for m in marks if m[0] == 'None']
# speed, felt accelerations, normal forces: the vertical line at `at`
assert len(lines) == 3 and np.allclose(lines, at, rtol=1e-9), (lines, at)
# the unrolled slide (arc length, distance along the wall) and 3-D: the
# contact's last record
last_s = f[f'rider/{who}/arc_length'][-1]
last_p = f[f'rider/{who}/position'][-1]
assert len(crosses) == 2, marks
assert abs(crosses[0][0] - last_s) < 1e-8 and abs(crosses[0][1] - f[f'rider/{who}/wall_distance'][-1]) < 1e-9, crosses
assert np.allclose(crosses[1], last_p, atol=1e-8), (crosses[1], last_p)
print('ok', who, at, len(marks), 'marks')
EOF
marks_rc=$?   # (not `$?` inside check: its message's substitutions reset it)
check '[ $marks_rc = 0 ]' "ejected rider, the plot's marks: $(cat "$work/marks.py.out") $(head -c 600 "$work/ride.marks")"

run ride_gate ride.nml --fail-on-limit
check '[ $got = 4 ]' "ejected rider, --fail-on-limit: exit status $got, expected 4 ($(cat "$work/ride_gate.err"))"
check 'grep -q "ejection" "$work/ride_gate.err"' "ejected rider, --fail-on-limit: the message names ejection: $(cat "$work/ride_gate.err")"

# 3. the same ride slower (2 m/s) stays in the flume to the end
run slow ride.nml --set rider%speed0=2.0
check '[ $got = 0 ]' "slower rider: exit status $got ($(cat "$work/slow.err"))"
check 'grep -q "^  ride ended  *end of the slide" "$work/slow.out"' "slower rider: $(grep 'ride ended' "$work/slow.out")"
check '! grep -q EJECTED "$work/slow.out"' "slower rider: an EJECTED line"
plot_marks slow.h5 >"$work/slow.marks" 2>&1
marks_rc=$?
check '[ $marks_rc = 0 ] && [ ! -s "$work/slow.marks" ]' "slower rider: the plot marks an ejection or failed: $(head -c 600 "$work/slow.marks")"
check 'grep -q "limit ejection <= 0: ok (closest 0 at" "$work/slow.out"' "slower rider: the ejection limit: $(grep 'ejection' "$work/slow.out")"

# 4. a unit that does not count
sed "s/limit_unit = '1'/limit_unit = 'm'/" "$work/ride.nml" >"$work/bad_unit.nml"
run bad_unit bad_unit.nml
check '[ $got = 1 ]' "ejection limit in m: exit status $got, expected 1"
check 'grep -q "unit .m. does not measure ejection" "$work/bad_unit.err"' "ejection limit in m: the message: $(cat "$work/bad_unit.err")"
check '! ls "$work"/bad_unit.h5* >/dev/null 2>&1' "ejection limit in m: a file was written"

echo "$checks checks, $failures failures"
[ "$failures" = 0 ]
