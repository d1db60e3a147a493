#!/usr/bin/env bash
# A ball resting on another a little off-centre (issue 25's stacks;
# docs/contact.md "Bodies that fall together"): its lowest point lies near
# the pole of its sphere's chart (v -> -pi/2, where r_u vanishes), where the
# start's support-point search ran into the edge of the parameter box. Before
# (main b4dfe43) such a start was refused (exit 1: "the support point lies
# beyond the edge of the parameter domain of the sphere") where the offset
# was along x, and where it was along y the small ball was SILENTLY put on
# the top (the search for big's point nearest to it stopped at big's pole,
# where every u meets the tangency conditions: moved 1 mm sideways, N the
# centred m g); the search now goes on in the chart regular there
# (contact_surface_search).
# Checked, the small ball (m = 0.057 kg) at rest on the big one (M = 0.6 kg)
# lying on a frictionless floor, its centre off the big one's top by theta
# (sin theta = d / 0.153 m, d = 1e-3 m and 1e-5 m along x and along y):
# exit 0, the first record's position of the small ball the given one
# (1e-9 m), and its normal force between them against the closed form of the
# instant at rest, the big ball pushed sideways on the floor:
#   N = m g cos(theta) / (1 + (m/M) sin(theta)^2)
# to 1e-9 relative (the closure's and the solver's rounding).
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
for offset in x1e-3 x1e-5 y1e-3 y1e-5; do
  "$py" - "$offset" >"$work/stack_$offset.nml" <<'PY'
import math
import sys
axis, d = sys.argv[1][0], float(sys.argv[1][1:])
dx, dy = (d, 0.0) if axis == "x" else (0.0, d)
dz = math.sqrt(0.153**2 - d**2)
print(f"""&run scenario = 'contact' /
&solver method = 'adams', rtol = 1e-10, atol = 1e-10, duration = 0.02, output_step = 0.01 /
&shape name = 'floor', kind = 'plane' /
&shape name = 'big', kind = 'sphere', radius = 0.12 /
&shape name = 'small', kind = 'sphere', radius = 0.033 /
&body name = 'big', mass = 0.6, solid_of = 'big', position = 0.0, 0.0, 0.12 /
&body name = 'small', mass = 0.057, solid_of = 'small', position = {dx!r}, {dy!r}, {0.12 + dz!r} /
&contact name = 'big_on_floor', shape_1 = 'floor', body_2 = 'big', shape_2 = 'big' /
&contact name = 'small_on_big', body_1 = 'big', shape_1 = 'big', body_2 = 'small', shape_2 = 'small' /""")
PY
  (cd "$work" && "$slidesim" -q -o "stack_$offset.h5" "stack_$offset.nml" >"stack_$offset.out" 2>"stack_$offset.err"); got=$?
  check '[ $got = 0 ]' "$offset: exit status $got: $(cat "$work/stack_$offset.err")"
  [ "$got" = 0 ] || continue
  out=$("$py" - "$work/stack_$offset.h5" "$offset" <<'PY' 2>&1
import math
import sys
import h5py
import numpy as np
c = h5py.File(sys.argv[1], "r")["contact"]
axis, d = sys.argv[2][0], float(sys.argv[2][1:])
g, m, big = 9.80665, 0.057, 0.6
bad = []
placed = c["bodies/small/position"][0]
given = np.array([d if axis == "x" else 0.0, d if axis == "y" else 0.0, 0.12 + math.sqrt(0.153**2 - d**2)])
if np.max(np.abs(placed - given)) > 1e-9:
    bad.append(f"the small ball starts at {placed}, given {given}")
s = d / 0.153
expected = m * g * math.sqrt(1 - s * s) / (1 + m / big * s * s)
got = c["contacts/small_on_big/normal_force"][0]
if abs(got / expected - 1) > 1e-9:
    bad.append(f"N = {got!r} N at the start, the closed form {expected!r} N ({got / expected - 1:.3g})")
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
  ); ok=$?
  check '[ $ok = 0 ]' "$offset: $out"
done
echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
