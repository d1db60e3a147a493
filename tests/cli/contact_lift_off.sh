#!/usr/bin/env bash
# A contact's lift-off ends the run normally only where its normal force
# really falls to zero (review finding 2):
#   dome      a ball slides off a fixed sphere from near its top: a true
#             lift-off (exit 0, complete file, the outcome says lift-off) at
#             the closed form cos(theta) = 2/3 cos(theta_0) of the sliding
#             particle (frictionless: the ball's spin does not matter);
#   singular  the paraboloids with paraboloid 3 far up the wall of the bowl
#             (review finding 2's input, 0.4 s): the two bowls meet in
#             conformal contact at t = 0.37273 s (0.37267 s with the old
#             default g = 9.81: t ~ g^-1/2), where the normal forces pass
#             through a pole (35 N and 8.5 N at the last output, -1e7 N and
#             more where they change sign). A failure: exit 2, the file kept
#             and marked incomplete, the message says singular, which
#             contacts and their forces. Where the steps pass the pole the
#             lift-off root there says so ("became singular ... at the event
#             at t = 0.372732 s"); where they close in on it without passing
#             (a Debug build on some machines: 30,222 steps, N = 1e12 N) the
#             runaway guard stops the run and its diagnosis says so ("grow
#             unbounded at t = 0.372732 s: the contact is becoming singular"),
#             never advising method = 'bdf';
#   drop      flight: a ball starting open lands (exit 0, "landing") at the
#             closed-form time and speed; sunk: an open start in the floor
#             is refused (exit 1); bounce: with restitution the ball bounces
#             until the contact closes, the impacts table, the phases and the
#             summary say so, and the energy balance (impacts, no force
#             law) is printed and stored, ~0;
#   two_balls two balls bouncing at once (inputs/contact/two_balls.nml), each
#             as alone; one comes to rest (its contact closes) while the
#             other bounces on; the report's spins (no rounding noise) and
#             the weights of the contact closed in the second phase;
#   stacked   inputs/contact/stacked_balls.nml: the impacts table's rows,
#             the two balls' impact naming both bodies, the hits on the
#             big ball resting on the floor (two rows at one time each);
#   walled    a ball carried by the floor slides into a wall it may land on:
#             one impact through the wall and the floor (an impact on a
#             carried body), and it slides back to the end (exit 0; it
#             failed there, exit 2, before that was built); rolling on the
#             floor, the same impact is not built: the run fails there
#             (exit 2, the file kept and marked incomplete).
set -u
slidesim=$1
repo=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"

cat > "$work/dome.nml" <<'EOF'
&run scenario = 'contact', output = 'dome.h5' /
&solver duration = 3, output_step = 0.01, rtol = 1e-10, atol = 1e-10 /
&shape name = 'dome', kind = 'ellipsoid', a = 1, b = 1, c = 1 /
&shape name = 'ball', kind = 'ellipsoid', a = 0.1, b = 0.1, c = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball', position = 0.05, 0, 1.1, angles_deg = 90, 0, 0 /
&contact name = 'ball_on_dome', body_1 = 'ground', shape_1 = 'dome', body_2 = 'ball', shape_2 = 'ball' /
EOF
run_case dome 0
grep -qF "lift-off: the normal force of contact 'ball_on_dome' fell to zero" "$work/dome.out" ||
  fail "dome: the summary does not say lift-off: $(grep 'stopped at' "$work/dome.out")"
if [ -n "$h5python" ] && [ -f "$work/dome.h5" ]; then
  # the ball's centre moves on the sphere of radius 1.1 m about the origin
  "$h5python" - "$work/dome.h5" <<'EOF' || fail "dome: lift-off angle"
import sys, h5py, numpy as np
r = h5py.File(sys.argv[1], 'r')['contact/bodies/ball/position'][:]
c0, c1 = (p[2] / np.linalg.norm(p) for p in (r[0], r[-1]))
ratio = c1 / (2 / 3 * c0)
print(f'dome: lift-off at cos(theta) = {c1:.10f}, closed form {2 / 3 * c0:.10f}')
sys.exit(0 if abs(ratio - 1) < 1e-7 else 1)   # rtol 1e-10 of the run, root located to 1e-14 s
EOF
fi

sed -e "s|output = 'paraboloids.h5'|output = 'singular.h5'|" -e "s|duration = 20.0|duration = 0.4|" \
    -e "s|position = 0.3, 0.2, 0.2|position = 1.0, 0.8, 0.6|" \
    -e "s|geometry_file = 'paraboloids/|geometry_file = '$repo/inputs/contact/paraboloids/|" \
    "$repo/inputs/contact/paraboloids.nml" > "$work/singular.nml"
grep -q "position = 1.0, 0.8, 0.6" "$work/singular.nml" || fail "singular: the input was not made"
run_case singular 2 'singular' "'p2_on_table' (N = " "'p3_in_p2' (N = " 'unbounded' 'not a lift-off' \
  't = 0.37273' 'conformal'
grep -q "use method = 'bdf'" "$work/singular.err" && fail "singular: the message advises bdf (a pole, not stiffness)"
grep -q 'stopped at .*lift-off' "$work/singular.out" && fail "singular: the summary still reports a lift-off"

# flight (issue 25, first slice): a ball that starts open above the floor
# falls and lands at t = sqrt(2 h/g), h = 1 m (0.451601 s), at sqrt(2 g h);
# the run ends there normally; an open start inside the floor is refused at
# its &contact's line
cat > "$work/drop.nml" <<'EOF'
&run scenario = 'contact', output = 'drop.h5' /
&solver duration = 2, output_step = 0.01, rtol = 1e-10, atol = 1e-10 /
&shape name = 'floor', kind = 'plane' /
&shape name = 'ball', kind = 'sphere', radius = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball', position = 0, 0, 1.1, velocity = 0.5, 0, 0 /
&contact name = 'on_floor', shape_1 = 'floor', body_2 = 'ball', shape_2 = 'ball', start = 'open' /
EOF
run_case drop 0
grep -qF "landing: the gap of contact 'on_floor' fell to zero at t = 0.451601 s, approaching at 4.428691 m/s" \
  "$work/drop.out" || fail "drop: the summary does not say the landing: $(grep 'stopped at' "$work/drop.out")"
sed -e "s|output = 'drop.h5'|output = 'sunk.h5'|" -e 's|position = 0, 0, 1.1|position = 0, 0, 0.09|' \
  "$work/drop.nml" > "$work/sunk.nml"
run_case sunk 1 "sunk.nml:6: &contact name = 'on_floor': start = 'open' but body 'ball' touches or overlaps"

# bounces: with restitution 0.5 the dropped ball bounces; the sixth rebound,
# 0.069 m/s, is below close_speed = 0.1 m/s: the contact closes there (a
# plastic impact) and the ball rests on the floor to the end; the impacts
# table holds the six, energy lost m/2 (v_(k-1)^2 - v_k^2), all of m/2 v_5^2
# at the closing; `open` marks the records in flight
sed -e "s|output = 'drop.h5'|output = 'bounce.h5'|" -e 's|, velocity = 0.5, 0, 0||' \
    -e "s|start = 'open'|start = 'open', restitution = 0.5, close_speed = 0.1|" "$work/drop.nml" > "$work/bounce.nml"
run_case bounce 0
grep -qE "impacts +6 " "$work/bounce.out" || fail "bounce: the summary does not count 6 impacts"
grep -qF "contact 'on_floor' closed at the impact at t = 1.326577 s" "$work/bounce.out" ||
  fail "bounce: the outcome does not say the contact closed"
grep -qF "the end of the simulated time" "$work/bounce.out" || fail "bounce: the run does not go on to the end"
# the energy balance with impacts and no force law (it was left out: only
# laws made it): E(t) - E(0) + the impacts' losses, ~0 (the bound below)
grep -qE "energy balance error +-?[0-9.]+E-(09|1[0-9]) \(E\(t\) - E\(0\) \+ impacts' losses" "$work/bounce.out" ||
  fail "bounce: the summary lacks the energy balance (or it is not below 1e-8): $(grep -i 'energy' "$work/bounce.out")"
if [ -n "$h5python" ] && [ -f "$work/bounce.h5" ]; then
  "$h5python" - "$work/bounce.h5" <<'EOF' || fail "bounce: the impacts table, the phases"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
t = f['contact/impacts']
v0 = np.sqrt(2 * 9.80665 * 1.0)
v = v0 * 0.5 ** np.arange(7)
v[6] = 0   # the closing impact is plastic
ok = (np.allclose(t['normal_speed_before'][:], -v[:6], atol=1e-8)
      and np.allclose(t['normal_speed_after'][:], v[1:], atol=1e-8)
      and np.allclose(t['energy_lost'][:], 0.5 * (v[:6] ** 2 - v[1:] ** 2), atol=1e-8)
      and list(t['contact'][:]) == [1] * 6
      # the bodies (issue 25 point 5): the ground (0) and the ball (&body 1)
      and list(t['body_1'][:]) == [0] * 6 and list(t['body_2'][:]) == [1] * 6
      and t['energy_lost'].attrs['units'] in (b'J', 'J'))
c = f['contact']
open_ = c['contacts/on_floor/open'][:]
time = c['time'][:]
switch = int(np.sum(open_))
ok = ok and open_[:switch].all() and not open_[switch:].any() and time[switch] == time[switch - 1]
ok = ok and abs(time[-1] - 2) < 1e-12 and abs(c['bodies/ball/position'][-1, 2] - 0.1) < 1e-9
ok = ok and abs(c['contacts/on_floor/normal_force'][-1] - 9.80665) < 1e-8
ok = ok and c['contacts/on_floor/open'].attrs['units'] in (b'1', '1')
print('bounce: impacts table and phases', 'match' if ok else 'differ', t['normal_speed_after'][:], switch)
# E(t) - E(0) + the energy the impacts removed up to t, every record, against
# the 9.8 J fallen. rtol = atol = 1e-10 bound each step's local error in z
# (~1 m) and v (<= 4.4 m/s) to ~2e-10 m and ~5e-10 m/s, ~5e-10 of the
# energy (m g dz, m v dv); the free flights are parabolas, which Adams
# follows to rounding, so the error comes from the restarts and the rest:
# seven phases (six flights, the closed contact), ~3.5e-9; bound 1e-8
balance = c['energy_balance'][:] if 'energy_balance' in c else None
if balance is None:
    print('bounce: no /contact/energy_balance')
    ok = False
else:
    scale = c['kinetic_energy'][:].max()
    worst = np.abs(balance).max() / scale
    print(f'bounce: energy balance at most {worst:.2e} of the {scale:.4f} J fallen')
    ok = ok and worst < 1e-8 and c['energy_balance'].attrs['units'] in (b'J', 'J') and len(balance) == len(time)
sys.exit(0 if ok else 1)
EOF
fi

# two balls at once (inputs/contact/two_balls.nml): each bounces on its own
# contact as alone (big: e = 0.5 from 1 m, small: e = 0.8 from 0.6 m); the
# big one's sixth rebound (0.069 m/s) is below close_speed: its contact
# closes there (a plastic impact) and it slides on while the small one
# bounces on to the end (exit 0), saying so; the impacts table names each
# impact's ball (body_2, body_names)
cp "$repo/inputs/contact/two_balls.nml" "$work/two_balls.nml"
run_case two_balls 0
grep -qF "contact 'big_on_floor' closed at the impact at t = 1.326577 s" "$work/two_balls.out" ||
  fail "two_balls: the outcome does not say where the big ball's contact closed"
grep -qE "impacts +10 " "$work/two_balls.out" || fail "two_balls: the summary does not count 10 impacts"
# the report: balls that never spin print no rounding noise (a spin of
# ~1e-14 rad/s, below 1e-9 of the turning scale, is 0), and the big ball's
# contact, closed only in the second phase, has its weights line, over the
# records where it is closed (it carries the big ball's weight; the records
# before it landed, open, with no force, are not counted)
grep -qE "^  big angular speed final +0 rad/s" "$work/two_balls.out" &&
  grep -qE "^  small angular speed max +0 rad/s" "$work/two_balls.out" ||
  fail "two_balls: the report prints rounding noise as the balls' angular speed"
grep -qF "big_on_floor normal force in weights 1.0000 / 1.0000 of big's weight (while closed)" "$work/two_balls.out" ||
  fail "two_balls: no weights line for the contact closed in a later phase: $(grep 'big_on_floor normal force in' \
    "$work/two_balls.out")"
if [ -n "$h5python" ] && [ -f "$work/two_balls.h5" ]; then
  "$h5python" - "$work/two_balls.h5" <<'EOF' || fail "two_balls: the impacts table"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
t = f['contact/impacts']
names = t['body_names'][()]
names = names.decode() if isinstance(names, bytes) else names
body = t['body_2'][:]
ok = names == '0 ground, 1 big, 2 small' and list(body) == [2, 1, 1, 2, 1, 1, 1, 1, 2, 2]
ok = ok and list(t['contact'][:]) == list(body) and list(t['body_1'][:]) == [0] * 10
for b, e, h in ((1, 0.5, 1.0), (2, 0.8, 0.6)):
    m = 0.2 if b == 1 else 0.5
    v = np.sqrt(2 * 9.80665 * h) * e ** np.arange(int(np.sum(body == b)) + 1)
    after = v[1:].copy()
    lost = (1 - e ** 2) * m / 2 * v[:-1] ** 2
    if b == 1:   # the sixth closes the contact: plastic, all its normal kinetic energy
        after[-1] = 0
        lost[-1] = m / 2 * v[-2] ** 2
    ok = ok and np.allclose(t['normal_speed_before'][body == b], -v[:-1], atol=1e-8)
    ok = ok and np.allclose(t['normal_speed_after'][body == b], after, atol=1e-8)
    ok = ok and np.allclose(t['energy_lost'][body == b], lost, atol=1e-8)
print('two_balls: impacts table', 'matches' if ok else 'differs', names, body)
sys.exit(0 if ok else 1)
EOF
fi

# a small ball dropped on a big one (inputs/contact/stacked_balls.nml): the
# big one's floor impact, then the two balls' (body_1 1 big, body_2 2
# small), then the big one's on the floor; at the end the small ball falls
# twice on the big one resting on the floor: each hit two rows at one time,
# the floor's and the hit's (exit 0: it failed at the first, exit 2, before
# a hit on a carried body was built)
cp "$repo/inputs/contact/stacked_balls.nml" "$work/stacked_balls.nml"
run_case stacked_balls 0
grep -qE "impacts +25 \(landings; 27 rows of /contact/impacts\)" "$work/stacked_balls.out" ||
  fail "stacked_balls: the summary does not count 25 impacts in 27 rows (the two last hits, two rows each)"
if [ -n "$h5python" ] && [ -f "$work/stacked_balls.h5" ]; then
  "$h5python" - "$work/stacked_balls.h5" <<'EOF' || fail "stacked_balls: the impacts table"
import sys, h5py
f = h5py.File(sys.argv[1], 'r')
t = f['contact/impacts']
names = t['body_names'][()]
names = names.decode() if isinstance(names, bytes) else names
ok = names == '0 ground, 1 big, 2 small'
c, b1, b2, time = list(t['contact'][:]), list(t['body_1'][:]), list(t['body_2'][:]), t['time'][:]
ok = ok and len(c) == 27 and c[:4] == [1, 2, 1, 1] and b1[:4] == [0, 1, 0, 0] and b2[:4] == [1, 2, 1, 1]
ok = ok and c[-4:] == [1, 2, 1, 2] and b1[-4:] == [0, 1, 0, 1] and b2[-4:] == [1, 2, 1, 2]
ok = ok and time[-4] == time[-3] and time[-2] == time[-1] and time[-1] > 5
print('stacked_balls: impacts table', 'matches' if ok else 'differs', names, t['body_1'][:], t['body_2'][:])
sys.exit(0 if ok else 1)
EOF
fi

cat > "$work/walled.nml" <<'EOF'
&run scenario = 'contact', output = 'walled.h5' /
&solver method = 'adams', rtol = 1e-10, atol = 1e-10, duration = 2, output_step = 0.01 /
&shape name = 'floor', kind = 'plane' /
&shape name = 'wall', kind = 'plane', origin = 1, 0, 0, angles_deg = 0, -90, 0 /
&shape name = 'ball', kind = 'sphere', radius = 0.1 /
&body name = 'ball', mass = 0.2, solid_of = 'ball', position = 0.2, 0, 0.1, velocity = 1, 0, 0 /
&contact name = 'on_wall', shape_1 = 'wall', body_2 = 'ball', shape_2 = 'ball', start = 'open', restitution = 0.8 /
&contact name = 'on_floor', shape_1 = 'floor', body_2 = 'ball', shape_2 = 'ball', start = 'closed' /
EOF
run_case walled 0
grep -qE "impacts +1 \(landings; 2 rows of /contact/impacts\)" "$work/walled.out" ||
  fail "walled: the summary does not count 1 impact in 2 rows (wall, floor)"
# the summary's body terms of a run whose phases changed mechanisms (they once read the
# first phase's frames: a height of 9e-285 m, a speed of 7e252 m/s)
grep -qE "ball height min / max +0.10000 / 0.10000 m" "$work/walled.out" ||
  fail "walled: the ball's height is not 0.1 m throughout (its summary terms)"
grep -qE "ball speed max +1.0000 m/s" "$work/walled.out" || fail "walled: the ball's speed max is not 1 m/s"
# ... and its contact terms: the floor carries the ball's weight, the body found by its name
# (looked up by frame, the first phase's frame matched none of the joined series' bodies,
# whose frames are the last phase's: "of body 2's weight")
grep -qE "on_floor normal force in weights +1.0000 / 1.0000 of ball's weight" "$work/walled.out" ||
  fail "walled: the floor's normal force is not 1 of the ball's weight: $(grep 'on_floor normal force in' \
    "$work/walled.out")"
sed -e "s/walled.h5/walled_rolling.h5/" -e "s/velocity = 1, 0, 0/velocity = 1, 0, 0, angular_velocity = 0, 10, 0/" \
  -e "s/start = 'closed' \//start = 'closed', rolling = .true. \//" "$work/walled.nml" > "$work/walled_rolling.nml"
# the same ball rolling on the floor (a rolling carrying contact) into the wall: one impact at the wall and
# the floor, the floor's no-slip rows in it (exit 2 before: "an impact through a rolling contact is not
# built"): the ball pivots about its floor point, its effective mass 7 m/5 at the centre, the wall's
# impulse (1 + e) (7 m/5) v = 0.504 N s, the floor's tangential (2/5) (1 + e) m v = 0.144 N s, the ball
# rolling back at e v = 0.8 m/s (test_rolling_impact checks the closed form to 1e-9)
run_case walled_rolling 0
grep -qE "impacts +1 \(landings; 2 rows of /contact/impacts\)" "$work/walled_rolling.out" ||
  fail "walled_rolling: the summary does not count 1 impact in 2 rows (wall, floor)"
if [ -n "$h5python" ] && [ -f "$work/walled_rolling.h5" ]; then
  "$h5python" - "$work/walled_rolling.h5" <<'EOF' || fail "walled_rolling: the impacts table"
import sys, h5py, numpy as np
t = h5py.File(sys.argv[1], 'r')['contact/impacts']
ok = list(t['contact'][:]) == [1, 2]
ok = ok and np.allclose(t['normal_impulse'][:], [0.504, 0], atol=1e-9)
ok = ok and np.allclose(t['tangential_impulse'][:], [0, 0.144], atol=1e-9)
ok = ok and np.allclose(t['normal_speed_after'][:], [0.8, 0], atol=1e-9)
print('walled_rolling: impacts table', 'matches' if ok else 'differs', t['normal_impulse'][:],
      t['tangential_impulse'][:], t['normal_speed_after'][:])
sys.exit(0 if ok else 1)
EOF
fi

finish
