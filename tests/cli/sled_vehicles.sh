#!/usr/bin/env bash
# The vehicles of &sled (docs/vehicles.md; their physics:
# tests/rider/test_vehicle.f90; the shipped inputs/parts/mat.nml, ring.nml
# and raft.nml run and are plotted through cli_every_input and
# cli_plot_scripts): what a vehicle cannot carry and the bar's own values
# given beside a vehicle are refused before any work (exit 1, no file), the
# message naming the group, the variable, the value and what is allowed; a
# mat rider and a ring ride the demo slide (exit 0) with the weight of
# vehicle and riders on the two contacts at the start.
slidesim=$1
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
. "$(dirname "$0")/support/checks.sh"
head="&run scenario = 'sled' /
&solver duration = 1.0, output_step = 0.01 /
&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /"
refused() {   # NAME EXPECTED SLED_GROUP
  local name=$1 expected=$2
  printf '%s\n%s\n' "$head" "$3" >"$work/$name.nml"
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$name.nml" >"$name.out" 2>"$name.err"); local got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1 ($(cat "$work/$name.err"))"
  check 'grep -qF -- "$expected" "$work/$name.err"' "$name: message lacks '$expected': $(cat "$work/$name.err")"
  check '! ls "$work/$name".h5* >/dev/null 2>&1' "$name: a result file (or a temporary one) was written"
}
refused ring_two "&sled: riders = 2 is not allowed: a ring carries 1 rider only" \
  "&sled vehicle = 'ring', riders = 2, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
refused raft_five "&sled: riders = 5 is not allowed" \
  "&sled vehicle = 'raft', riders = 5, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
refused mat_mass "&sled: mass" \
  "&sled vehicle = 'mat', mass = 80, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
refused bar_riders "&sled: riders" \
  "&sled riders = 2, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
refused small_child "&sled: scale = 0.5 is not allowed" \
  "&sled vehicle = 'sitting', scale = 0.5, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
refused boat "&sled: vehicle = 'boat' is not allowed" \
  "&sled vehicle = 'boat', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
# a vehicle wider than the slide (the demo slide: a tube of radius 0.5 m,
# 1 m across) is refused with both widths and where (exit 1, no file); on
# 2572e9e a 1.2 m ring rode the 1 m tube (exit 0)
refused ring_too_wide "&sled: vehicle = 'ring' is not allowed: it is 1.2 m wide, but the slide's section at arc length 0 m is only 1 m wide across its bottom" \
  "&sled vehicle = 'ring', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
refused raft_too_wide "&sled: vehicle = 'raft' is not allowed: it is 1.94 m wide" \
  "&sled vehicle = 'raft', riders = 4, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
# a mat rider and a sitting child down the demo slide for a second: the two
# normal forces at the start carry the weight of the vehicle and its riders
# (on the straight entry, slope 12 deg: M g cos 12 deg, M = 1.5 + 73.0 kg for
# the mat and an adult, 73.0 x 0.8^3 kg for the child sitting up); the
# felt acceleration at the start is (-mu cos 12, 0, cos 12) g along the
# vehicle's axes, the summary and its JSON give the vehicle's figures
for spec in "mat 1.0 74.5" "sitting 0.8 37.376"; do
  set -- $spec
  name=$1
  printf '%s\n%s\n' "$head" "&sled vehicle = '$name', scale = $2, friction = 'coulomb', mu = 0.07, water = 'dry',
  u0 = 0.5, v0 = 1.5707963267948966, du0 = 2 /" >"$work/$name.nml"
  (cd "$work" && "$slidesim" -o "$name.h5" --summary-json "$name.json" "$name.nml" >"$name.out" 2>"$name.err"); got=$?
  check '[ $got = 0 ]' "$name on the demo slide: exit $got: $(cat "$work/$name.err")"
  check 'grep -q "felt normal min / max" "$work/$name.out" && grep -q "vehicle top speed" "$work/$name.out"' \
    "$name: the summary lacks the vehicle's figures: $(cat "$work/$name.out")"
  check 'grep -q "\"vehicle_felt_normal_max\"" "$work/$name.json"' "$name: the JSON lacks vehicle_felt_normal_max"
  check 'grep -q "narrowest section  *1.0000* m across its bottom" "$work/$name.out"' \
    "$name: the summary lacks the narrowest section: $(cat "$work/$name.out")"
  "$python" - "$work/$name.h5" "$3" <<'PY' || { echo "FAIL $name: the normal forces or the felt acceleration (above)"; failures=$((failures + 1)); }
import sys, math
import h5py
with h5py.File(sys.argv[1], "r") as f:
    n = f["/sled/contacts/rear/normal_force"][0] + f["/sled/contacts/front/normal_force"][0]
expected = float(sys.argv[2]) * 9.80665 * math.cos(math.radians(12.0))
# the start is on the straight entry: the sum is the weight's normal part
# to the closure's and the solve's rounding
if abs(n - expected) > 1e-9 * expected:
    print(f"N_rear + N_front = {n} N, expected {expected} N")
    sys.exit(1)
with h5py.File(sys.argv[1], "r") as f:
    felt = f["/sled/vehicle/felt_acceleration"][0]
    units = f["/sled/vehicle/felt_acceleration"].attrs["units"]
    units = units.decode() if isinstance(units, bytes) else units
c = math.cos(math.radians(12.0))
# exact but for the closure's rounding
if max(abs(felt[0] + 0.07 * c), abs(felt[1]), abs(felt[2] - c)) > 1e-9 or units != "gravity":
    print(f"felt acceleration at the start {felt} {units}, expected ({-0.07 * c}, 0, {c}) gravity")
    sys.exit(1)
PY
done
# limits (docs/vehicles.md, "Limits"): a sitting child down the demo slide
# for a second speeds up from 2 m/s to 3.37 m/s on the entry: speed
# <= 3 m/s is exceeded, felt normal >= 0.9 g holds (cos 12 deg = 0.978 g on
# the straight entry); the summary says so, exit 0 without asking, exit 4
# with --fail-on-limit (the file complete); quantities a vehicle does not
# have, limits on the bar and --fail-on-limit without limits are refused
# (on 2572e9e &sled knew no limit_quantity)
limits="limit_quantity = 'speed', 'acceleration_normal', 'exit_speed', limit_unit = 'm/s', 'g', 'km/h',
  limit_max = 3.0, limit_min(2) = 0.9, limit_max(3) = 36.0"
printf '%s\n%s\n' "$head" "&sled vehicle = 'sitting', scale = 0.8, friction = 'coulomb', mu = 0.07, water = 'dry',
  u0 = 0.5, v0 = 1.5707963267948966, du0 = 2, $limits /" >"$work/limits.nml"
(cd "$work" && "$slidesim" -o limits.h5 --summary-json limits.json limits.nml >limits.out 2>limits.err); got=$?
check '[ $got = 0 ]' "limits without asking: exit $got, expected 0: $(cat "$work/limits.err")"
check 'grep -q "LIMIT EXCEEDED: speed <= 3 m/s; worst 3.36" "$work/limits.out" && grep -q "limit acceleration_normal >= 0.9 g: ok (closest 0.97" "$work/limits.out"' \
  "limits: the verdicts are not in the summary: $(cat "$work/limits.out")"
check 'grep -q "\"limits_exceeded\": *1" "$work/limits.json"' "limits: the JSON lacks limits_exceeded = 1: $(cat "$work/limits.json")"
# the verdicts in the result file (/sled/vehicle/limits, as the ride's
# /evaluation/limits; on 3e73489 only in the summary): each from the
# vehicle's own series in the same file (a maximum's worst is the largest
# speed, where is the rear contact's arc length at that record, the demo
# slide's u), the exit speed not judged (1 s does not reach the end), the
# width check's figures (a child of scale 0.8: 0.8 x 0.40 m; the demo
# slide's tube 1 m across)
"$python" - "$work/limits.h5" <<'PY' || { echo "FAIL limits: the verdicts in the result file (above)"; failures=$((failures + 1)); }
import sys
import h5py
import numpy as np
def text(d):
    v = d[()]
    return v.decode() if isinstance(v, bytes) else str(v)
bad = []
with h5py.File(sys.argv[1], "r") as f:
    g = f["/sled/vehicle"]
    speed = g["speed"][:]
    felt = g["felt_acceleration"][:]
    u = f["/sled/coordinates/u/value"][:]
    s = g["limits/1_speed"]
    i = int(np.argmax(speed))
    if text(s["verdict"]) != "exceeded" or s["maximum"][()] != 3.0 or text(s["given_unit"]) != "m/s" \
            or s["worst"][()] != speed[i] or abs(s["worst_arc_length"][()] - u[i]) > 1e-9 \
            or abs(s["excess"][()] - (speed[i] - 3.0)) > 1e-12 or not s["first_arc_length"][()] <= u[i] \
            or s["worst"].attrs["units"] not in (b"m/s", "m/s"):
        bad.append(f"1_speed: {dict((k, s[k][()]) for k in s)}, largest speed {speed[i]} at u = {u[i]}")
    a = g["limits/2_acceleration_normal"]
    if text(a["verdict"]) != "ok" or a["minimum"][()] != 0.9 or a["worst"][()] != felt[:, 2].min() \
            or a["excess"][()] != 0 or "first_arc_length" in a or a["worst"].attrs["units"] not in (b"gravity", "gravity"):
        bad.append(f"2_acceleration_normal: {dict((k, a[k][()]) for k in a)}, smallest {felt[:, 2].min()}")
    e = g["limits/3_exit_speed"]
    if text(e["verdict"]) != "not judged" or "worst" in e or abs(e["maximum"][()] - 10.0) > 1e-12:
        bad.append(f"3_exit_speed: {dict((k, e[k][()]) for k in e)}")
    if abs(g["width"][()] - 0.32) > 1e-12 or abs(g["narrowest_section"][()] - 1.0) > 1e-3 \
            or "narrowest_section_arc_length" not in g:
        bad.append(f"width {g['width'][()]}, narrowest section {g['narrowest_section'][()]}")
for b in bad:
    print(b)
sys.exit(1 if bad else 0)
PY
(cd "$work" && "$slidesim" --fail-on-limit -o limits4.h5 limits.nml >limits4.out 2>limits4.err); got=$?
check '[ $got = 4 ] && grep -q "limits exceeded: 1 speed" "$work/limits4.err" && [ -f "$work/limits4.h5" ]' \
  "--fail-on-limit: exit $got, expected 4 with the file: $(cat "$work/limits4.err")"
refused lever_arm "&sled: limit_quantity(1) = 'lever_arm' is not allowed: a vehicle's ride is judged on speed" \
  "&sled vehicle = 'mat', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1, limit_quantity = 'lever_arm', limit_unit = 'm', limit_max = 0.1 /"
refused bar_limits "the bar has no ride figures" \
  "&sled u0 = 0.5, v0 = 1.5707963267948966, du0 = 1, limit_quantity = 'speed', limit_unit = 'm/s', limit_max = 10 /"
printf '%s\n%s\n' "$head" "&sled vehicle = 'mat', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /" >"$work/nolimits.nml"
(cd "$work" && "$slidesim" --fail-on-limit -o nolimits.h5 nolimits.nml >nolimits.out 2>nolimits.err); got=$?
check '[ $got = 1 ] && grep -q "there is no limit to fail on: set limits in &sled" "$work/nolimits.err"' \
  "--fail-on-limit without limits: exit $got: $(cat "$work/nolimits.err")"
# the double ring (1.2 m wide) in the bowl slide's 1.2 m flume fits; on
# 2572e9e it stopped with exit 2 at t = 3.16 s, its front contact "left the
# parameter domain" at v = -5.73 rad on the straight entry: the closure's
# retries after a rejected trial step started from that step's solution
# 4.7 m ahead (docs/vehicles.md). Now it rides into the bowl until its rear
# lifts off at t = 4.2058 s, u = 13.368 m, as the same run with max_step =
# 0.01 s (which never jumped) does: to 1e-3 s and 1 cm (rtol 1e-10 runs
# agree to ~1e-6; the stop is a root of the normal force, located to 1e-9)
printf '%s\n' "&run scenario = 'sled' /
&solver method = 'adams', rtol = 1e-10, atol = 1e-9, duration = 30.0, output_step = 0.01 /
&surface kind = 'slide', geometry_file = '$root/inputs/parts/bowl_slide.nml' /
&sled vehicle = 'double_ring', riders = 2, friction = 'coulomb', mu = 0.0724419, water = 'dry',
  u0 = 0.5, v0 = 1.5707963267948966, du0 = 1.0 /" >"$work/bowl_ring.nml"
(cd "$work" && "$slidesim" -o bowl_ring.h5 --summary-json bowl_ring.json bowl_ring.nml >bowl_ring.out 2>bowl_ring.err); got=$?
check '[ $got = 0 ] && grep -q "lift-off: the normal force of contact .rear. fell to zero" "$work/bowl_ring.out"' \
  "the double ring in the bowl: exit $got, expected 0 and a rear lift-off: $(cat "$work/bowl_ring.out" "$work/bowl_ring.err")"
"$python" - "$work/bowl_ring.json" <<'PY' || { echo "FAIL the double ring in the bowl: where it lifted off (above)"; failures=$((failures + 1)); }
import json, sys
d = json.load(open(sys.argv[1]))
d = d["values"]
t, u = d["simulated_time"], d["u_final"]
if abs(t - 4.205761) > 1e-3 or abs(u - 13.368) > 0.01:
    print(f"lift-off at t = {t} s, u = {u} m; expected 4.2058 s, 13.368 m")
    sys.exit(1)
PY
# ejection (docs/vehicles.md, "Limits"; refused for a vehicle before, while
# a vehicle does go over a wall's top, ending its run with exit 0): the ring
# of inputs/parts/bowl_halfpipe_ring.nml started at 15 m/s climbs the
# half-pipe's right wall and goes over its top on the entry straight (the
# run stops at the side edge); a limit ejection <= 0 is exceeded (exit 4
# with --fail-on-limit, the file complete); at the shipped 1 m/s it is met
ring_input=$root/inputs/parts/bowl_halfpipe_ring.nml
eject_limit=(--set "sled%limit_quantity='ejection'" --set "sled%limit_unit='1'" --set "sled%limit_max=0")
(cd "$work" && "$slidesim" --fail-on-limit -o eject.h5 --summary-json eject.json --set sled%du0=15 "${eject_limit[@]}" \
  "$ring_input" >eject.out 2>eject.err); got=$?
check '[ $got = 4 ] && grep -q "stopped at  *over the side edge" "$work/eject.out" && grep -q "LIMIT EXCEEDED: ejection <= 0; worst 1" "$work/eject.out" && [ -f "$work/eject.h5" ]' \
  "a ring over the wall's top: exit $got, expected 4 and ejection exceeded: $(cat "$work/eject.out" "$work/eject.err")"
check 'grep -q "\"limits_exceeded\": *1" "$work/eject.json"' "the ring over the wall: the JSON's limits_exceeded"
(cd "$work" && "$slidesim" --fail-on-limit -o kept.h5 "${eject_limit[@]}" "$ring_input" >kept.out 2>kept.err); got=$?
check '[ $got = 0 ] && grep -q "stopped at  *end of slide" "$work/kept.out" && grep -q "limit ejection <= 0: ok (closest 0 " "$work/kept.out"' \
  "the shipped ring with an ejection limit: exit $got, expected 0 and the limit met: $(cat "$work/kept.out" "$work/kept.err")"
# up the wall (docs/vehicles.md, "How high it climbs"; on 3e73489 a
# vehicle's wall angle was refused): a mat started 0.2 rad up the demo
# slide's tube (radius 0.5 m) on its straight entry: both contacts at wall
# angle 0.2 rad (+: towards +v), 0.1 m along the wall, at the start; a
# limit wall_angle <= 5 deg is judged on the larger of the two contacts'
# |angle| at each record (the file's own series), exceeded at the start
printf '%s\n%s\n' "$head" "&sled vehicle = 'mat', friction = 'coulomb', mu = 0.07, water = 'dry', u0 = 0.5,
  v0 = 1.7707963267948966, du0 = 2, limit_quantity = 'wall_angle', limit_unit = 'deg', limit_max = 5.0 /" >"$work/wall.nml"
(cd "$work" && "$slidesim" -o wall.h5 --summary-json wall.json wall.nml >wall.out 2>wall.err); got=$?
check '[ $got = 0 ] && grep -q "rear wall angle max" "$work/wall.out" && grep -q "LIMIT EXCEEDED: wall_angle <= 5 deg" "$work/wall.out"' \
  "a mat up the wall: exit $got or the summary lacks the wall angle: $(cat "$work/wall.out" "$work/wall.err")"
"$python" - "$work/wall.h5" <<'PY' || { echo "FAIL a mat up the wall (above)"; failures=$((failures + 1)); }
import sys, math
import h5py
import numpy as np
bad = []
with h5py.File(sys.argv[1], "r") as f:
    g = f["/sled/vehicle"]
    angle = np.array([g["rear/wall_angle"][:], g["front/wall_angle"][:]])
    distance = np.array([g["rear/wall_distance"][:], g["front/wall_distance"][:]])
    # the rear is the start's (u0, v0), the front the closure's (1e-10)
    if abs(angle[0, 0] - 0.2) > 1e-12 or abs(angle[1, 0] - 0.2) > 1e-8 or np.max(np.abs(distance[:, 0] - 0.1)) > 1e-8:
        bad.append(f"at the start: wall angles {angle[:, 0]} rad, distances {distance[:, 0]} m; expected 0.2, 0.1")
    worst = np.max(np.abs(angle)) * 180 / math.pi
    lim = g["limits/1_wall_angle"]
    if abs(lim["worst"][()] - worst) > 1e-9 * worst or lim["verdict"][()] not in (b"exceeded", "exceeded"):
        bad.append(f"limit: worst {lim['worst'][()]} deg, the series' largest {worst} deg, verdict {lim['verdict'][()]}")
for b in bad:
    print(b)
sys.exit(1 if bad else 0)
PY
# in the water (docs/vehicles.md, "In the water"; on 3e73489 a vehicle rode
# dry only): a mat rider in the demo slide's water (the default &water),
# the water's drag at both contacts from the start (the water starts at
# the slide's top), /water written beside /sled, the summary saying so; the
# contacts' friction_force is the friction alone, mu N along minus the slip
# (the drag is not summed into it: on the old recorder it was), the
# energy balance closes with the drag's work (the integration's rtol)
printf '%s\n%s\n' "$head" "&sled vehicle = 'mat', friction = 'coulomb', mu = 0.07, u0 = 0.5,
  v0 = 1.5707963267948966, du0 = 2 /" >"$work/wet.nml"
(cd "$work" && "$slidesim" -o wet.h5 --summary-json wet.json wet.nml >wet.out 2>wet.err); got=$?
check '[ $got = 0 ] && grep -q "water  *computed, 0.004 m^3/s, end of slide (its drag at both contacts)" "$work/wet.out"' \
  "the mat in the water: exit $got or the summary lacks the water: $(cat "$work/wet.out" "$work/wet.err")"
# with a second inlet downstream the water line's flow rate is the start's:
# it says so, and gives the flow at the end (the summary said 0.004 m^3/s
# alone, with 6 l/s flowing past the inlet)
printf '%s\n' "&inlet arc_length = 30.0, flow_rate = 0.002, speed = 3.0 /" | cat "$work/wet.nml" - >"$work/wet_inlet.nml"
(cd "$work" && "$slidesim" -o wet_inlet.h5 wet_inlet.nml >wet_inlet.out 2>wet_inlet.err); got=$?
check '[ $got = 0 ] && grep -q "water  *computed, 0.004 m^3/s at the start, 0.006 m^3/s at the end (1 of 1 inlets joined), end of slide (its drag at both contacts)" "$work/wet_inlet.out"' \
  "the mat in the water of two inlets: exit $got or the summary's water line: $(grep water "$work/wet_inlet.out") $(cat "$work/wet_inlet.err")"
"$python" - "$work/wet.h5" <<'PY' || { echo "FAIL the mat in the water (above)"; failures=$((failures + 1)); }
import sys
import h5py
import numpy as np
bad = []
with h5py.File(sys.argv[1], "r") as f:
    if "/water/speed" not in f:
        bad.append("no /water/speed")
    for c in ("rear", "front"):
        law = f[f"/sled/laws/{c}_water_drag"]
        if law["active"][0] != 1 or not np.linalg.norm(law["force"][0]) > 1e-3:
            bad.append(f"{c}: the drag at the start: active {law['active'][0]}, force {law['force'][0]} N")
        n = f[f"/sled/contacts/{c}/normal_force"][:]
        fr = f[f"/sled/contacts/{c}/friction_force"][:]
        slip = f[f"/sled/contacts/{c}/velocity"][:]
        expected = -0.07 * n[:, None] * slip / np.linalg.norm(slip, axis=1)[:, None]
        # Coulomb's regularization: (eps/|w|)^2/2 relative at the slip speeds here
        if np.max(np.abs(fr - expected)) > 1e-6 * np.max(np.abs(expected)):
            bad.append(f"{c}: friction_force is not mu N against the slip: {np.max(np.abs(fr - expected))} N off")
    balance = f["/sled/energy_balance"][:]
    scale = np.max(np.abs(f["/sled/kinetic_energy"][:] - f["/sled/kinetic_energy"][0])) if "/sled/kinetic_energy" in f else 1e3
    if np.max(np.abs(balance)) > 1e-5 * max(scale, 1.0):
        bad.append(f"energy balance off by {np.max(np.abs(balance))} J")
for b in bad:
    print(b)
sys.exit(1 if bad else 0)
PY
# what the water needs, or a dry ride would not use, is refused (exit 1, no
# file): the water's groups or its properties riding dry, a vehicle on a
# surface without water unless it says water = 'dry', water for the bar
refused dry_water_group "&water is not read: the sled rides dry" \
  "&sled vehicle = 'mat', water = 'dry', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /
&water flow_rate = 0.01 /"
refused dry_density "&sled: water_density = 998 is not allowed: they describe the water's drag, and the sled rides dry" \
  "&sled vehicle = 'mat', water = 'dry', water_density = 998, u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
refused bar_water "&sled: water = 'computed' is not allowed: the water's drag acts on a vehicle's contacts" \
  "&sled water = 'computed', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /"
printf '%s\n%s\n%s\n' "&run scenario = 'sled' /" "&solver duration = 1.0, output_step = 0.01 /" \
  "&surface kind = 'plane' /
&sled vehicle = 'mat', u0 = 0.5, v0 = 0.5, du0 = 1 /" >"$work/plane_wet.nml"
(cd "$work" && "$slidesim" -q -o plane_wet.h5 plane_wet.nml >plane_wet.out 2>plane_wet.err); got=$?
check '[ $got = 1 ] && grep -q "water = .computed. is not allowed: the water is computed on a slide" "$work/plane_wet.err" && ! ls "$work"/plane_wet.h5* >/dev/null 2>&1' \
  "a mat on a plane without water = 'dry': exit $got: $(cat "$work/plane_wet.err")"
sed -i "s/&sled vehicle = 'mat',/\&sled vehicle = 'mat', water = 'dry',/" "$work/plane_wet.nml"
(cd "$work" && "$slidesim" -q -o plane_dry.h5 plane_wet.nml >plane_dry.out 2>plane_dry.err); got=$?
check '[ $got = 0 ]' "a mat on a plane with water = 'dry': exit $got: $(cat "$work/plane_dry.err")"
# a water that fails before the vehicle rides (the half-pipe's default
# water starts subcritical, docs/water.md): exit 2, the file kept with its
# /water, marked incomplete with the water's reason
printf '%s\n' "&run scenario = 'sled' /
&solver duration = 1.0, output_step = 0.01 /
&surface kind = 'slide', geometry_file = '$root/inputs/parts/halfpipe_slide.nml' /
&sled vehicle = 'ring', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1 /" >"$work/ring_critical.nml"
(cd "$work" && "$slidesim" -q -o ring_critical.h5 ring_critical.nml >ring_critical.out 2>ring_critical.err); got=$?
check '[ $got = 2 ] && grep -q "the water the vehicle rides in: water at the start: the flow reached critical" "$work/ring_critical.err"' \
  "a failed water: exit $got, expected 2: $(cat "$work/ring_critical.err")"
"$python" - "$work/ring_critical.h5" <<'PY' || { echo "FAIL a failed water: the file (above)"; failures=$((failures + 1)); }
import sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    status = f.attrs["status"]
    status = status.decode() if isinstance(status, bytes) else status
    if status != "incomplete" or "water" not in f:
        print(f"status {status}, groups {list(f)}")
        sys.exit(1)
PY
# flight (docs/vehicles.md, "Flight"): only a vehicle flies; the landing's
# law and the flight limits need may_fly
refused bar_flies "&sled: may_fly = .true. is not allowed: a vehicle flies" \
  "&sled u0 = 0.5, v0 = 1.5707963267948966, du0 = 1, may_fly = .true. /"
refused landing_without_flight "&sled: landing_restitution" \
  "&sled vehicle = 'mat', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1, landing_restitution = 0.3 /"
refused airtime_without_flight "&sled: limit_quantity(1) = 'airtime' is not allowed: airtime limits a flight: it needs may_fly = .true." \
  "&sled vehicle = 'mat', u0 = 0.5, v0 = 1.5707963267948966, du0 = 1, limit_quantity = 'airtime', limit_unit = 's', limit_max = 0.1 /"
# a mat over the jump that may fly (inputs/parts/mat_jump.nml): its front
# lifts off at the lip, then its rear; it lands and rides on to the end of
# the slide (exit 0); the flights in the summary, the JSON and the file, the
# airtime and drop_height limits judged. Without may_fly the front's
# lift-off ends the run where the flying one's first take-off is.
sed -e "s|'jump_slide.nml'|'$root/inputs/parts/jump_slide.nml'|" "$root/inputs/parts/mat_jump.nml" >"$work/mat_jump.nml"
(cd "$work" && "$slidesim" -o mat_jump.h5 --summary-json mat_jump.json mat_jump.nml >mat_jump.out 2>mat_jump.err); got=$?
check '[ $got = 0 ] && grep -q "the front contact opens (may_fly)" "$work/mat_jump.out" && grep -q "stopped at .*end of slide" "$work/mat_jump.out" && grep -q "landing 1 (front)" "$work/mat_jump.out" && grep -q "limit airtime <= 1 s: ok" "$work/mat_jump.out"' \
  "a mat over the jump that may fly: exit $got: $(cat "$work/mat_jump.out" "$work/mat_jump.err")"
sed -e "s|may_fly = .true., landing_restitution = 0.0|may_fly = .false.|" -e "/limit_/d" "$work/mat_jump.nml" >"$work/mat_stays.nml"
(cd "$work" && "$slidesim" -o mat_stays.h5 --summary-json mat_stays.json mat_stays.nml >mat_stays.out 2>mat_stays.err); got=$?
check '[ $got = 0 ] && grep -q "lift-off: the normal force of contact .front. fell to zero" "$work/mat_stays.out"' \
  "the mat over the jump without may_fly: exit $got: $(cat "$work/mat_stays.out" "$work/mat_stays.err")"
"$python" - "$work/mat_jump.json" "$work/mat_jump.h5" "$work/mat_stays.json" <<'PY' || { echo "FAIL a mat over the jump that may fly (above)"; failures=$((failures + 1)); }
import json, sys
import h5py
import numpy as np
d = json.load(open(sys.argv[1]))["values"]
stays = json.load(open(sys.argv[3]))["values"]
bad = []
if not (d["flights"] >= 1 and d["whole_flights"] >= 1 and d["landings"] >= 2 and 0 < d["airtime"] < 1):
    bad.append(f"flights {d['flights']}, whole {d['whole_flights']}, landings {d['landings']}, airtime {d['airtime']}")
with h5py.File(sys.argv[2], "r") as f:
    g = f["/sled/vehicle"]
    opened = g["open"][:]
    t = f["/sled/time"][:]
    land = g["flight/landing/time"][:]
    drop = g["flight/landing/drop_height"][:]
    speed = g["flight/landing/normal_speed"][:]
    if opened.shape != t.shape or not np.any(opened == 3):
        bad.append(f"/sled/vehicle/open: {opened.shape} for {t.shape} records, the whole mat in the air at none")
    first = t[np.argmax(opened != 0)]
    if abs(first - stays["simulated_time"]) > 1e-9:
        bad.append(f"the first take-off at t = {first} s, the run without flight lifted off at {stays['simulated_time']} s")
    if not np.all(np.isin(land, t)):
        bad.append("a landing without its records")
    if np.max(np.abs(drop - speed**2 / (2 * 9.80665))) > 1e-12:
        bad.append(f"drop heights {drop} are not v_n^2/(2 g) of {speed}")
    # a take-off or landing: two records at one time, the same pose
    same = np.flatnonzero(np.diff(t) == 0)
    r = f["/sled/bodies/bar_mass/position"][:]
    if len(same) < 4 or np.max(np.abs(r[same + 1] - r[same])) > 1e-9:
        bad.append(f"{len(same)} switches, pose jumps {np.max(np.abs(r[same + 1] - r[same])) if len(same) else 0}")
if bad:
    print("; ".join(bad))
    sys.exit(1)
PY
# the mat's pitch over the jump is its true pitch in every record: where the
# rear is on the slide (its contact point moves along the slide's tangent;
# phi = 0 and v = 90 deg all the way, so the heading's x is that tangent and
# the pitch axis the bar's y) the pitch from the bar's frame, atan2(-x.n,
# x.t) with n = t x y, equals /sled/coordinates/pitch (1e-9 rad), and the
# summary's pitch min / max are that dataset's extremes. On c24c13b the
# pitch was written 0 wherever the front's closure solved it: the summary
# said -2.4963 / 8.7864 deg, the bar's frame gives -17.92 deg with both
# contacts on (record 96; the check failed there by 0.313 rad)
"$python" - "$work/mat_jump.json" "$work/mat_jump.h5" <<'PY' || { echo "FAIL the mat's pitch over the jump (above)"; failures=$((failures + 1)); }
import json, sys
import h5py
import numpy as np
d = json.load(open(sys.argv[1]))["values"]
bad = []
with h5py.File(sys.argv[2], "r") as f:
    opened = f["/sled/vehicle/open"][:]
    pitch = f["/sled/coordinates/pitch/value"][:]
    # rows of the stored rotation are the bar's axes (the file's C order)
    rot = f["/sled/bodies/bar_mass/rotation"][:]
    vel = f["/sled/contacts/rear/velocity"][:]
    phi = f["/sled/coordinates/phi/value"][:]
on = np.flatnonzero((opened & 1) == 0)
x, y = rot[on, 0, :], rot[on, 1, :]
t = vel[on] / np.linalg.norm(vel[on], axis=1)[:, None]
n = np.cross(t, y)
framed = np.arctan2(-np.sum(x * n, axis=1), np.sum(x * t, axis=1))
if np.max(np.abs(phi)) > 1e-12:
    bad.append(f"phi up to {np.max(np.abs(phi))} rad: the check's frame needs phi = 0")
worst = np.max(np.abs(framed - pitch[on]))
if worst > 1e-9:
    i = on[np.argmax(np.abs(framed - pitch[on]))]
    bad.append(f"the pitch recorded differs from the bar's frame's by {worst} rad (record {i}: {pitch[i]} vs the frame's {framed[np.argmax(np.abs(framed - pitch[on]))]}, open {opened[i]})")
if not (d["pitch_min"] == np.min(pitch) and d["pitch_max"] == np.max(pitch)):
    bad.append(f"the summary's pitch min / max {d['pitch_min']} / {d['pitch_max']} rad, the records' {np.min(pitch)} / {np.max(pitch)}")
if not (d["pitch_min"] <= np.min(framed) and d["pitch_max"] >= np.max(framed)):
    bad.append(f"the summary's pitch min / max {d['pitch_min']} / {d['pitch_max']} rad do not hold the bar's frame's {np.min(framed)} / {np.max(framed)}")
if bad:
    print("; ".join(bad))
    sys.exit(1)
PY
# the same double ring through the bowl with may_fly (bowl_ring.nml above,
# landings plastic), to t = 4.25 s: on c24c13b it ended with exit 2 at
# t = 4.2223 s, "contact 'front' became singular", 17 ms after its rear
# lifted off: the front's closure solved for the pitch where the front's
# normal lies across the rear's. Now the closure solves for the heading
# there (a switch at t = 4.1247 s, both contacts still on) and the rear
# lifts off at 4.2058 s as without may_fly. On one contact the roll is free
# (a rigid body on one point contact): without the held roll's couple the
# rear presses on, sinks back by 1e-6 m within 1 ms and the run fails part
# way (exit 2) with that cause in its message (docs/vehicles.md "Flight":
# the model has no state with both contacts on and the roll free). At every
# switch (two records at one time) the coordinates u, v, phi, pitch,
# rear_lift, roll and their rates are continuous (1e-9); the energy
# balance holds (1e-6). The failed run keeps what it computed: the file
# (marked incomplete) has /sled/vehicle's figures at every record (speed,
# felt acceleration, the open contacts: the rear's at the last) and the
# summary its one closure switch (on 8f2e33d neither was written)
sed -e "s|duration = 30.0|duration = 4.25|" -e "s|du0 = 1.0 /|du0 = 1.0, may_fly = .true., landing_restitution = 0.0 /|" \
  "$work/bowl_ring.nml" >"$work/bowl_ring_fly.nml"
(cd "$work" && "$slidesim" -o bowl_ring_fly.h5 --summary-json bowl_ring_fly.json bowl_ring_fly.nml >bowl_ring_fly.out 2>bowl_ring_fly.err); got=$?
check '[ $got = 2 ] && grep -q "the rear contact.s landing: it leaves the slide .* it sank back by 1.00000E-06 m .* after its take-off, before it had risen: where it took off its normal force was zero with both contacts on and the roll held; in the flight.s build, the roll free (a rigid body on one point contact), the rear presses on: the held roll.s couple lifted it" "$work/bowl_ring_fly.err"' \
  "the double ring flying through the bowl: exit $got (expected 2, the cause named): $(cat "$work/bowl_ring_fly.out" "$work/bowl_ring_fly.err")"
"$python" - "$work/bowl_ring_fly.h5" "$work/bowl_ring_fly.json" <<'PY' || { echo "FAIL the double ring flying through the bowl (above)"; failures=$((failures + 1)); }
import json, sys
import h5py
import numpy as np
bad = []
d = json.load(open(sys.argv[2]))["values"]
if abs(d["energy_balance_error"]) > 1e-6:
    bad.append(f"energy balance error {d['energy_balance_error']}")
if d.get("front_closure_switches") != 1:
    bad.append(f"the summary's front closure switches {d.get('front_closure_switches')}, not 1")
with h5py.File(sys.argv[1], "r") as f:
    if f.attrs["status"] != "incomplete":
        bad.append(f"the file is marked {f.attrs['status']}, not incomplete")
    t = f["/sled/time"][:]
    vg = f.get("/sled/vehicle")
    if vg is None:
        bad.append("the failed run's file has no /sled/vehicle")
    else:
        for name in ("width", "speed", "felt_acceleration", "open", "flight"):
            if name not in vg:
                bad.append(f"the failed run's file has no /sled/vehicle/{name}")
        if "speed" in vg and (vg["speed"].shape != t.shape or not np.all(np.isfinite(vg["speed"][:]))
                              or not np.all(vg["speed"][:] > 0)):
            bad.append(f"/sled/vehicle/speed {vg['speed'].shape} not a speed > 0 at each of the {t.shape} records")
        if "felt_acceleration" in vg and vg["felt_acceleration"].shape != (len(t), 3):
            bad.append(f"/sled/vehicle/felt_acceleration {vg['felt_acceleration'].shape}, not {(len(t), 3)}")
        if "open" in vg and (vg["open"].shape != t.shape or vg["open"][-1] != 1 or vg["open"][0] != 0):
            bad.append(f"/sled/vehicle/open {vg['open'][:]}: not both on at the start and the rear open at the end")
    c = f["/sled/coordinates"]
    names = sorted(c.keys())
    if names != ["phi", "pitch", "rear_lift", "roll", "u", "v"]:
        bad.append(f"the coordinates {names}, not the full layout")
    # two switches (two records at one time): the front's closure, the rear's take-off
    same = np.flatnonzero(np.diff(t) == 0)
    if len(same) != 2 or abs(t[same[0]] - 4.1247) > 1e-3 or abs(t[same[-1]] - 4.205761) > 1e-3:
        bad.append(f"switches at {t[same]} s (expected the closure's at 4.1247 s, the rear's take-off at 4.2058 s)")
    else:
        lift_off = t[same[-1]]
        lift = c["rear_lift"]["value"][:]
        if not (lift_off < t[-1] < lift_off + 2e-3) or np.any(lift[t > lift_off] > 0) or lift[-1] > -1e-6 * 0.999:
            bad.append(f"after the take-off at {lift_off} s the rear rose, or did not sink 1e-6 m, or the run went on to {t[-1]} s")
        if not abs(c["roll"]["value"][-1]) > 0:
            bad.append("the roll did not move on one contact")
    for i in same:
        jq = max(abs(c[n]["value"][i + 1] - c[n]["value"][i]) for n in names)
        jv = max(abs(c[n]["rate"][i + 1] - c[n]["rate"][i]) for n in names)
        if jq > 1e-9 or jv > 1e-9:
            bad.append(f"at t = {t[i]} s the coordinates jump by {jq}, their rates by {jv}")
    # phi is the heading at every record, also where the closure solves it
    phi = c["phi"]["value"][:]
    if len(same) and np.any(phi[t > t[same[0]]] == 0):
        bad.append("phi is 0 at records after the switch")
if bad:
    print("; ".join(bad))
    sys.exit(1)
PY
# the plain bar has no vehicle figures (its results as before)
printf '%s\n%s\n' "$head" "&sled u0 = 0.5, v0 = 1.5707963267948966, du0 = 2 /" >"$work/bar.nml"
(cd "$work" && "$slidesim" -o bar.h5 bar.nml >bar.out 2>&1); got=$?
check '[ $got = 0 ] && ! grep -q "vehicle top speed" "$work/bar.out"' "the bar: exit $got or vehicle figures: $(cat "$work/bar.out")"
echo "sled_vehicles: $checks checks, $failures failed"
[ "$failures" = 0 ]
