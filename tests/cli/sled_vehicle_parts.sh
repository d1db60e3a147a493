#!/usr/bin/env bash
# A vehicle's own parts and each rider's size from input (&sled mat_length,
# mat_width, mat_thickness, mat_mass, ring_radii, ring_mass, raft_radii,
# raft_mass, raft_floor, scales; docs/vehicles.md "The input"; their
# physics: tests/rider/test_vehicle.f90): a part of another kind of
# vehicle, a value out of its range or one that cannot be (a torus with
# r >= R, a floor above the tube) is refused before any work (exit 1, no
# file), the message naming the file's line, the group, the variable, the
# value and what is allowed; the width check follows the input's sizes (a
# raft made wider than the half-pipe is refused, the default one is not;
# a mat made wider than the demo tube likewise); a double ring of small
# tori with a child and an adult rides the demo slide with the weight of
# its input masses on the two contacts.
slidesim=$1
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
. "$(dirname "$0")/support/checks.sh"
head="&run scenario = 'sled' /
&solver duration = 1.0, output_step = 0.01 /
&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /"
start="u0 = 0.5, v0 = 1.5707963267948966, du0 = 1, water = 'dry'"
refused() {   # NAME EXPECTED SLED_GROUP [SURFACE]
  local name=$1 expected=$2
  if [ $# -gt 3 ]; then
    printf '%s\n%s\n%s\n%s\n' "&run scenario = 'sled' /" "&solver duration = 1.0, output_step = 0.01 /" "$4" "$3" \
      >"$work/$name.nml"
  else
    printf '%s\n%s\n' "$head" "$3" >"$work/$name.nml"
  fi
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$name.nml" >"$name.out" 2>"$name.err"); local got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1 ($(cat "$work/$name.err"))"
  check 'grep -qF -- "$expected" "$work/$name.err"' "$name: message lacks '$expected': $(cat "$work/$name.err")"
  check '! ls "$work/$name".h5* >/dev/null 2>&1' "$name: a result file (or a temporary one) was written"
}
# a part of another kind of vehicle (on 91d1a1f the names were unknown)
refused ring_on_mat "ring_on_mat.nml:4: &sled: ring_radii = 0.5, 0.2 is not allowed: the vehicle 'mat' has no ring (vehicle = 'ring' or 'double_ring' only)" \
  "&sled vehicle = 'mat', ring_radii = 0.5, 0.2, $start /"
refused mat_on_raft "&sled: mat_length = 1.2 is not allowed: the vehicle 'raft' has no mat (vehicle = 'mat' only)" \
  "&sled vehicle = 'raft', riders = 2, mat_length = 1.2, $start /"
refused floor_on_ring "&sled: raft_floor = 0.1 is not allowed: the vehicle 'double_ring' is not a raft (vehicle = 'raft' only)" \
  "&sled vehicle = 'double_ring', raft_floor = 0.1, $start /"
refused scales_on_bar "&sled: scales = 0.8 is not allowed: they describe a vehicle: give vehicle too" \
  "&sled scales = 0.8, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
# values that cannot be
refused torus_fat "&sled: ring_radii = 0.3, 0.3 is not allowed: the tube's radius r (the second) must be > 0 and less than R" \
  "&sled vehicle = 'ring', ring_radii = 0.3, 0.3, $start /"
refused floor_high "&sled: raft_floor = 0.5 is not allowed: must lie in [0, 2 r] = [0, 0.44] m" \
  "&sled vehicle = 'raft', riders = 3, raft_floor = 0.5, $start /"
refused ring_heavy "&sled: ring_mass = 500 is not allowed: must be a finite number in [0.5, 100] (kg)" \
  "&sled vehicle = 'ring', ring_mass = 500, $start /"
refused child_too_small "&sled: scales(2) = 0.4 is not allowed" \
  "&sled vehicle = 'double_ring', riders = 2, scales = 1.0, 0.4, $start /"
refused three_scales "&sled: scales" \
  "&sled vehicle = 'double_ring', riders = 2, scales = 1.0, 0.8, 0.7, $start /"
# a subscript beyond the riders names the index given (was "index 1 must lie in [1, 1]")
refused scales_index "&sled: scales(2): the subscript is not allowed: index 2 of scales lies outside [1, 1] (riders = 1)" \
  "&sled vehicle = 'mat', scales(2) = 0.8, $start /"
refused scale_unused "&sled: scale = 0.9 is not allowed: scales gives every rider's size (scale is for those it does not give)" \
  "&sled vehicle = 'double_ring', riders = 2, scale = 0.9, scales = 1.0, 0.6, $start /"
# the width check follows the input's sizes: the half-pipe slide is 4 m
# across; the default raft (1.94 m) fits, one of R = 1.5 m, r = 0.6 m
# (4.2 m) does not; the demo tube is 1 m across: the default mat (0.6 m)
# fits (cli_sled_vehicles), one 1.2 m wide does not
halfpipe="&surface kind = 'slide', geometry_file = '$root/inputs/parts/halfpipe_slide.nml' /"
refused raft_wide "&sled: vehicle = 'raft' is not allowed: it is 4.2 m wide, but the slide's section at arc length" \
  "&sled vehicle = 'raft', riders = 4, raft_radii = 1.5, 0.6, $start /" "$halfpipe"
printf '%s\n%s\n%s\n%s\n' "&run scenario = 'sled' /" "&solver duration = 1.0, output_step = 0.01 /" "$halfpipe" \
  "&sled vehicle = 'raft', riders = 4, $start /" >"$work/raft_fits.nml"
(cd "$work" && "$slidesim" --check raft_fits.nml >raft_fits.out 2>raft_fits.err); got=$?
check '[ $got = 0 ]' "the default raft on the half-pipe slide: exit $got, expected 0: $(cat "$work/raft_fits.err")"
refused mat_wide "&sled: vehicle = 'mat' is not allowed: it is 1.2 m wide, but the slide's section at arc length 0 m is only 1 m wide" \
  "&sled vehicle = 'mat', mat_width = 1.2, $start /"
# a double ring of two small tori (R = 0.35 m, r = 0.12 m: 0.94 m across,
# it fits the demo tube), 9 kg each, a child of scale 0.6 in front and an
# adult of 1.08 behind, down the demo slide for a second: on the straight
# entry (12 deg) N_rear + N_front = M g cos 12 deg with
# M = 2 x 9 + 73.0 (0.6^3 + 1.08^3) kg (to the closure's rounding), the
# width and the contacts' distance 4 R + 2 r = 1.64 m those of the input
printf '%s\n%s\n' "$head" "&sled vehicle = 'double_ring', riders = 2, scales = 0.6, 1.08, ring_radii = 0.35, 0.12,
  ring_mass = 9, friction = 'coulomb', mu = 0.07, $start /" >"$work/small_rings.nml"
(cd "$work" && "$slidesim" -o small_rings.h5 small_rings.nml >small_rings.out 2>small_rings.err); got=$?
check '[ $got = 0 ]' "the small double ring: exit $got: $(cat "$work/small_rings.err")"
"$python" - "$work/small_rings.h5" <<'PY' || { echo "FAIL the small double ring (above)"; failures=$((failures + 1)); }
import sys, math
import h5py
import numpy as np
bad = []
with h5py.File(sys.argv[1], "r") as f:
    n = f["/sled/contacts/rear/normal_force"][0] + f["/sled/contacts/front/normal_force"][0]
    width = f["/sled/vehicle/width"][()]
    rear = f["/sled/contacts/rear/position"][0]
    front = f["/sled/contacts/front/position"][0]
mass = 2 * 9.0 + 73.0 * (0.6**3 + 1.08**3)
expected = mass * 9.80665 * math.cos(math.radians(12.0))
if abs(n - expected) > 1e-9 * expected:
    bad.append(f"N_rear + N_front = {n} N, expected {expected} N (M = {mass} kg)")
if abs(width - 0.94) > 1e-12:
    bad.append(f"width {width} m, expected 2 (R + r) = 0.94 m")
# on the straight entry the contacts lie on one line: their distance is L
if abs(np.linalg.norm(front - rear) - 1.64) > 1e-9:
    bad.append(f"contacts {np.linalg.norm(front - rear)} m apart, expected 4 R + 2 r = 1.64 m")
if bad:
    print("; ".join(bad))
    sys.exit(1)
PY
echo "sled_vehicle_parts: $checks checks, $failures failed"
[ "$failures" = 0 ]
