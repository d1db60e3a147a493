#!/usr/bin/env bash
# The worked example of docs/geometry.md ("A bowl and a half-pipe in one
# slide"): inputs/parts/bowl_halfpipe_slide.nml and a mat and a ring down it
# (bowl_halfpipe_mat.nml, bowl_halfpipe_ring.nml), each checked against
# physics and the docs' formulas, not against its own earlier output:
# - the slide loses the sum of its elements' height losses (the transitions
#   are symmetric about the joints; the bowl's gradient varies along its
#   spiral, so its two windows keep its loss only to ~1e-4 m: 4.1e-5 m here,
#   1.3e-4 m on bowl_slide.nml, while halfpipe_slide.nml's loss is the sum
#   to the bit), and in its bowl the centerline lies on
#   the sphere of radius rho_in/sin(slope) at the distance
#   rho_in - sigma sin(beta) from its axis, cot(beta) = 2 pi turns/ln(rho_in/rho_out)
#   (docs/geometry.md, "The bowl");
# - each vehicle starts at du0/cos(10 deg) (du0 is the rate of the slide's
#   u, on an 'exact' chain the horizontal length); on the entry straight its
#   contacts carry M g cos(10 deg) together, the front the share
#   (x_c + mu z_c)/L of docs/vehicles.md's table (the water's drag has no
#   normal part); in the half-pipe curve it climbs the outer (right) wall:
#   under its centre of mass to the bank angle atan(v^2/(g R)) on average;
#   on the run-out (2 deg, the water's drag there below 1 W) it slows at
#   g (mu cos a - sin a) (within 3 %: it still swings across the U); it
#   never goes faster than the frictionless sqrt(v0^2 + 2 g dz).
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
for name in slide mat ring; do
  (cd "$root/inputs/parts" && "$slidesim" -q -o "$work/$name.h5" --summary-json "$work/$name.json" \
     "bowl_halfpipe_$name.nml" >"$work/$name.out" 2>"$work/$name.err"); got=$?
  check '[ $got = 0 ]' "bowl_halfpipe_$name.nml: exit status $got ($(cat "$work/$name.err"))"
done
"$py" - "$work" >"$work/physics.out" 2>&1 <<'EOF'
import json
import math
import sys

import h5py
import numpy as np

work = sys.argv[1]
g = 9.80665
problems = []


def close(what, got, want, tol):
    line = f"{what}: {got:.10g} against {want:.10g} (tolerance {tol:g})"
    print(line)
    if not abs(got - want) <= tol:
        problems.append(line)


# the slide: the elements of bowl_halfpipe_slide.nml
tand = lambda a: math.tan(math.radians(a))
curve = 8.0 * math.radians(120.0)              # the curve's horizontal length
losses = 8.0 * tand(10) + curve * tand(4) + 4.0 * tand(8) + 2.5 + 10.0 * tand(14) + 8.0 * tand(2)
with open(f"{work}/slide.json") as f:
    close("height drop (m)", json.load(f)["values"]["drop"], losses, 5e-4)   # the bowl's windows: above
rho_in, slope, drop, turns = 10.0, math.radians(45.0), 2.5, 0.75
R = rho_in / math.sin(slope)
rho_out = math.sqrt(R**2 - (drop + R * math.cos(slope))**2)
beta = math.atan(math.log(rho_in / rho_out) / (2 * math.pi * turns))
entry = 8.0 + curve + 4.0                      # sigma at the bowl's entry joint
length = (rho_in - rho_out) / math.sin(beta)
with h5py.File(f"{work}/slide.h5", "r") as f:
    u = f["/geometry/centerline/u"][...]
    p = np.asarray(f["/geometry/centerline/points"][...])
p = p.T if p.shape[0] == 3 else p
core = (u > entry + 1.0 + 1e-6) & (u < entry + length - 1.0 - 1e-6)   # between the bowl's windows
x, y, z = p[core].T
# the sphere through the core points: x^2 + y^2 + z^2 = 2 a x + 2 b y + 2 c z + d
A = np.column_stack([2 * x, 2 * y, 2 * z, np.ones_like(x)])
(a, b, c, d), *_ = np.linalg.lstsq(A, x**2 + y**2 + z**2, rcond=None)
print(f"{core.sum()} centerline points in the bowl's core, sigma {u[core][0]:.3f} to {u[core][-1]:.3f} m")
close("bowl sphere radius (m)", math.sqrt(d + a * a + b * b + c * c), R, 1e-6)
rho = np.hypot(x - a, y - b)
worst = np.abs(rho - (rho_in - (u[core] - entry) * math.sin(beta))).max()
close("bowl: axis distance against rho_in - sigma sin(beta), worst (m)", worst, 0.0, 1e-6)
close("bowl: the outlet's axis distance rho_out (m)", rho_in - length * math.sin(beta), 6.6143783, 1e-6)

# the vehicles: M, x_c, z_c, L of docs/vehicles.md's table (scale 1)
mu = 0.0724419
for name, M, xc, zc, L in (("mat", 74.5, 0.50, 0.111, 1.00), ("ring", 80.0, 0.61, 0.411, 0.90)):
    with h5py.File(f"{work}/{name}.h5", "r") as f:
        s = f["/sled"]
        t = s["time"][...]
        u = s["coordinates/u/value"][...]
        speed = s["vehicle/speed"][...]
        rear, front = s["contacts/rear/normal_force"][...], s["contacts/front/normal_force"][...]
        angles = [s[f"vehicle/{c}/wall_angle"][...] for c in ("rear", "front")]
        drag_power = np.abs(s["laws/rear_water_drag/power"][...]) + np.abs(s["laws/front_water_drag/power"][...])
        z = [np.asarray(s[f"contacts/{c}/position"][...]) for c in ("rear", "front")]
    z = [q.T if q.shape[0] == 3 else q for q in z]
    close(f"{name}: start speed (m/s) against du0/cos(10 deg)", speed[0], 1.0 / math.cos(math.radians(10)), 1e-9)
    i = np.searchsorted(t, 0.5)                 # on the entry straight (u < 7: before its transition)
    assert u[i] < 7.0, u[i]
    close(f"{name}: N_rear + N_front on the entry (N) against M g cos(10 deg)", rear[i] + front[i],
          M * g * math.cos(math.radians(10)), 1e-9 * M * g)
    close(f"{name}: the front's share on the entry against (x_c + mu z_c)/L", front[i] / (rear[i] + front[i]),
          (xc + mu * zc) / L, 2e-3)
    # the curve's core (both contacts between its transitions: sigma 9 to 23.7)
    m = (u > 10.0) & (u < 22.0)
    bank = math.degrees(math.atan(speed[m].mean()**2 / (g * 8.0)))
    centre = (1 - xc / L) * angles[0] + (xc / L) * angles[1]   # at the centre of mass, between the contacts
    close(f"{name}: the mean wall angle under its centre of mass in the half-pipe curve (deg) "
          "against -atan(v^2/(g R))", math.degrees(centre[m].mean()), -bank, 1.5)
    # the run-out's core (sigma 78.5 to 85.5, the front 1 m ahead)
    m = (u > 79.0) & (u < 83.0)
    assert drag_power[m].max() < 1.0, drag_power[m].max()
    slope_rate = np.polyfit(t[m], speed[m], 1)[0]
    a2 = math.radians(2.0)
    close(f"{name}: deceleration on the run-out (m/s^2) against g (mu cos a - sin a)", -slope_rate,
          g * (mu * math.cos(a2) - math.sin(a2)), 0.03 * g * (mu * math.cos(a2) - math.sin(a2)))
    height = (z[0][:, 2] + z[1][:, 2]) / 2
    bound = np.sqrt(speed[0]**2 + 2 * g * np.maximum(height[0] - height, 0.0))
    print(f"{name}: exit speed {speed[-1]:.4f} m/s, {speed[-1] / bound[-1]:.3f} of the frictionless "
          f"sqrt(v0^2 + 2 g dz) = {bound[-1]:.4f} m/s")
    if np.any(speed > bound + 1e-9):
        problems.append(f"{name}: faster than the frictionless bound")
for problem in problems:
    print("PROBLEM " + problem)
sys.exit(1 if problems else 0)
EOF
rc=$?
check '[ $rc = 0 ]' "bowl and half-pipe against physics: $(grep PROBLEM "$work/physics.out"; tail -3 "$work/physics.out")"
# a start beyond the slide's end: u0 = 86 m is inside the centreline's
# 86.09 m of arc length but beyond the chain's horizontal length (8 + 16.755
# + 4 + 38.746 + 10 + 8 = 85.502 m); the refusal names the domain's bounds,
# v as a flume's [-wall/radius, pi + wall/radius]
(cd "$root/inputs/parts" && "$slidesim" --check --set sled%u0=86 bowl_halfpipe_ring.nml >"$work/beyond.out" 2>&1); got=$?
check '[ $got = 1 ] && grep -q ": &sled: u0, v0 = 86.0, 1.5707963267948966 is not allowed: the start must lie in the parameter domain of the slide of 6 elements (straight, curve, straight, bowl, straight, runout) with a flume section (centerline length 86.090 m): u in \[0.0, 85.50207[0-9]*\], v in \[-0.8333333[0-9]*, 3.974925[0-9]*\]" "$work/beyond.out"' \
  "a start beyond the chain's horizontal length: exit $got: $(cat "$work/beyond.out")"
echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
