#!/usr/bin/env bash
# A ball in a spherical bowl through its bottom (issue 27, point 7), R = 1 m,
# r = 0.1 m, frictionless, from rest 19.4 degrees up the wall (centre path of
# radius L = R - r = 0.9 m), against closed forms: sliding, the ball does not
# turn and its centre is a pendulum of length L; rolling, (7/10) m L^2
# theta'^2 - m g L cos(theta) is conserved, a pendulum of length 7 L / 5.
# Large-amplitude periods T = 4 sqrt(L_eq/g) K(sin(theta0/2)) (K by the AGM),
# from the zero crossings of the centre's x (a cubic through the 4 samples
# around each: error ~1e-9 s at output_step 0.01 s); rtol 1e-10: 1e-6 of T;
# energy to 1e-7 of the largest kinetic energy.
# The bowl's poles (issue 27, point 7): a bowl in its natural orientation
# (poles on the vertical) has its bottom at a pole of (3.57); its surface
# joint changes chart there (docs/contact.md, "Charts"), so the ball passes
# through the bottom with the same closed-form periods, sliding (open chain:
# S1's (u1, v1) change chart, phi takes the turn) and rolling (loop: S12's
# and S1's; with the ball's own poles on the vertical too, S2's as well).
# main stopped every natural case at the pole, exit 2 ("reached the pole
# v = -1.570796"). The bowls turned poles-horizontal (angles_deg = 90, 0, 0,
# the former workaround) still run, without chart changes of the bowl.
set -u
slidesim=$1
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"

bowl() {   # bowl NAME BOWL_ANGLES CONTACT_EXTRA
  cat > "$work/$1.nml" <<NML
&run scenario = 'contact', output = '$1.h5' /
&solver rtol = 1e-10, atol = 1e-10, duration = 4.0, output_step = 0.01 /
&shape name = 'bowl', kind = 'ellipsoid', a = 1.0, b = 1.0, c = 1.0, angles_deg = $2 /
&shape name = 'ball', kind = 'ellipsoid', a = 0.1, b = 0.1, c = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball', position = 0.3, 0, -0.85, angles_deg = 90, 0, 0 /
&contact name = 'c', body_1 = 'ground', shape_1 = 'bowl', side_1 = -1, body_2 = 'ball', shape_2 = 'ball' $3 /
NML
}

# chart_changes NAME: the summary's count of chart changes.
chart_changes() {
  sed -n 's/^ *chart changes *\([0-9]*\).*/\1/p' "$work/$1.out"
}

bowl natural '0, 0, 0' ''
run_case natural 0
bowl natural_rolling '0, 0, 0' ', rolling = .true.'
run_case natural_rolling 0
bowl natural_ball_rolling '0, 0, 0' ', rolling = .true.'
sed -i 's/, angles_deg = 90, 0, 0 \//\//' "$work/natural_ball_rolling.nml"   # the ball's poles vertical too
run_case natural_ball_rolling 0
bowl sliding '90, 0, 0' ''
run_case sliding 0
# A bowl tilted by its own angles_deg: its pole 10 degrees off the bottom, on
# the ball's path in the x-z plane (a placed surface: it forwards the
# ellipsoid's charts; main stopped at the pole, exit 2). A turned sphere is
# the same sphere: the same closed-form periods.
bowl tilted '0, 10, 0' ''
run_case tilted 0
bowl tilted_rolling '0, 10, 0' ', rolling = .true.'
run_case tilted_rolling 0
bowl rolling '90, 0, 0' ', rolling = .true.'
run_case rolling 0
for name in natural natural_rolling natural_ball_rolling tilted tilted_rolling; do
  checks=$((checks + 1))
  [ "$(chart_changes $name)" -ge 1 ] 2>/dev/null || fail "$name: no chart change through the pole: $(cat "$work/$name.out")"
done
checks=$((checks + 1))
[ "$(chart_changes sliding)" = "" ] || fail "sliding: the turned bowl changed charts: $(cat "$work/sliding.out")"

# Starting at the pole: the ball (its own poles vertical too) at the bottom
# with 0.5 m/s along x (rolling: 5 rad/s about y, no slip), so both
# surfaces' contact points start at their poles; the joints change chart at
# the placement, before the closure (main: exit 1, "the closure Jacobian is
# singular"). The amplitude from the energy: 1 - cos(theta0) = f v0^2 /
# (2 g L), f = 1 sliding, 7/5 rolling; the same periods.
kick() {   # kick NAME CONTACT_EXTRA BODY_EXTRA
  cat > "$work/$1.nml" <<NML
&run scenario = 'contact', output = '$1.h5' /
&solver rtol = 1e-10, atol = 1e-10, duration = 4.0, output_step = 0.01 /
&shape name = 'bowl', kind = 'ellipsoid', a = 1.0, b = 1.0, c = 1.0 /
&shape name = 'ball', kind = 'ellipsoid', a = 0.1, b = 0.1, c = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball', position = 0, 0, -0.9, velocity = 0.5, 0, 0 $3 /
&contact name = 'c', body_1 = 'ground', shape_1 = 'bowl', side_1 = -1, body_2 = 'ball', shape_2 = 'ball' $2 /
NML
}
kick kick '' ''
run_case kick 0
kick kick_rolling ', rolling = .true.' ', angular_velocity = 0, 5, 0'
run_case kick_rolling 0
# the velocity level changes no charts: its start at a pole is refused (it
# would take the loop's coordinates of another chart as its surfaces' own)
kick kick_velocity ", level = 'velocity'" ''
run_case kick_velocity 1 "&contact name = 'c': at velocity level a contact cannot start at" 'use level = '"'"'position'"'"

# A ball orbiting the bottom (sliding, no spin: a spherical pendulum of length
# L = 0.9 m), from 12 degrees off-centre with 0.3 m/s across (the conical
# pendulum's speed there would be 0.62 m/s): its orbit closes to 5.8 degrees
# around the pole, inside the chart margin (10 degrees), so S1 changes chart
# with both u1' and v1' non-zero and phi takes the turn (the ball's poles
# horizontal: the only change; main ran it without one). Energy and the
# angular momentum about the vertical, m (x y' - y x'), are conserved (the
# normal force passes through the bowl's centre on the axis, gravity is
# vertical): 1e-7 of the largest kinetic energy and of L_z (rtol 1e-10
# drifts both by ~1e-8 over 4 s, chart change or not; a wrong rate mapping
# at the change would jump the velocity by O(1)).
cat > "$work/orbit.nml" <<NML
&run scenario = 'contact', output = 'orbit.h5' /
&solver rtol = 1e-10, atol = 1e-10, duration = 4.0, output_step = 0.01 /
&shape name = 'bowl', kind = 'ellipsoid', a = 1.0, b = 1.0, c = 1.0 /
&shape name = 'ball', kind = 'ellipsoid', a = 0.1, b = 0.1, c = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball', position = 0.18712, 0, -0.88033, velocity = 0, 0.3, 0,
  angles_deg = 90, 0, 0 /
&contact name = 'c', body_1 = 'ground', shape_1 = 'bowl', side_1 = -1, body_2 = 'ball', shape_2 = 'ball' /
NML
run_case orbit 0
checks=$((checks + 1))
[ "$(chart_changes orbit)" -ge 1 ] 2>/dev/null || fail "orbit: no chart change near the pole: $(cat "$work/orbit.out")"

[ -n "$h5python" ] || { echo "SKIP: the periods need python3 with h5py"; finish; }
for case in natural:1.0 natural_rolling:1.4 natural_ball_rolling:1.4 sliding:1.0 rolling:1.4 kick:1.0 \
            kick_rolling:1.4 tilted:1.0 tilted_rolling:1.4; do
  name=${case%%:*}; factor=${case#*:}
  checks=$((checks + 1))
  out=$("$h5python" - "$work/$name.h5" "$factor" <<'PY'
import sys
import h5py
import numpy as np

f = h5py.File(sys.argv[1])
g = f["contact"]
t = g["time"][:]
r = g["bodies/ball/position"][:]
length, gravity = 0.9, 9.80665   # the contact scenario's default gravity
theta0 = np.arctan2(r[0, 0], -r[0, 2])
if abs(theta0) < 1e-9:   # from the bottom: the amplitude from the energy
    speed = np.linalg.norm(g["bodies/ball/velocity"][0])
    theta0 = np.arccos(1 - float(sys.argv[2]) * speed**2 / (2 * gravity * length))
k = np.sin(theta0 / 2)
a, b = 1.0, np.sqrt(1 - k * k)
for _ in range(40):
    a, b = (a + b) / 2, np.sqrt(a * b)
period = 4 * np.sqrt(float(sys.argv[2]) * length / gravity) * np.pi / (2 * a)
x = r[:, 0]
crossings = []
for i in np.nonzero((np.sign(x[:-1]) != np.sign(x[1:])) & (t[:-1] > 0.05))[0]:
    j = slice(max(i - 1, 0), i + 3)
    c = np.polyfit(t[j] - t[i], x[j], 3)
    roots = [z.real for z in np.roots(c) if abs(z.imag) < 1e-12 and -1e-9 <= z.real <= t[i + 1] - t[i] + 1e-9]
    crossings.append(t[i] + roots[0])
bad = []
if len(crossings) < 3:
    bad.append(f"only {len(crossings)} passes through the bottom in {t[-1]} s")
else:
    measured = crossings[2] - crossings[0]
    if abs(measured - period) > 1e-6 * period:
        bad.append(f"period {measured!r} s, closed form {period!r} s (theta0 {np.degrees(theta0):.3f} deg)")
energy = g["energy"][:]
if np.abs(energy - energy[0]).max() > 1e-7 * g["kinetic_energy"][:].max():
    bad.append(f"energy changed by {np.abs(energy - energy[0]).max():.3g} J")
print("; ".join(bad))
PY
) || fail "$name: check failed: $out"
  [ -z "$out" ] || fail "$name: $out"
done

checks=$((checks + 1))
out=$("$h5python" - "$work/orbit.h5" <<'PY'
import sys
import h5py
import numpy as np

g = h5py.File(sys.argv[1])["contact"]
r = g["bodies/ball/position"][:]
v = g["bodies/ball/velocity"][:]
lz = r[:, 0] * v[:, 1] - r[:, 1] * v[:, 0]
tilt = np.degrees(np.arccos(-r[:, 2] / np.linalg.norm(r, axis=1)))
bad = []
if np.abs(lz - lz[0]).max() > 1e-7 * abs(lz[0]):
    bad.append(f"L_z changed by {np.abs(lz - lz[0]).max():.3g} of {lz[0]:.6g}")
energy = g["energy"][:]
if np.abs(energy - energy[0]).max() > 1e-7 * g["kinetic_energy"][:].max():
    bad.append(f"energy changed by {np.abs(energy - energy[0]).max():.3g} J")
if not tilt.min() < 10:
    bad.append(f"the orbit stays {tilt.min():.2f} degrees from the pole: outside the chart margin")
print("; ".join(bad))
PY
) || fail "orbit: check failed: $out"
[ -z "$out" ] || fail "orbit: $out"

finish
