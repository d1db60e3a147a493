#!/usr/bin/env bash
# What a new user met in the reports (closing note 14, "Noticed and left alone"):
# - the geometry summary called a slide from &slide_elements a "tube
#   surface": it names its elements and section (the bowl slide's four in
#   order; the demo slide's eight counted by kind), in the summary, the log
#   and the file's root attribute `surface`; a tube on &centerline is still
#   a tube surface;
# - the point mass's normal force was signed along the frame's z (-15 N in
#   a bowl): it is the pressing force, positive while the mass presses,
#   checked against closed forms: circling inside a sphere of radius R at
#   50 deg from the bottom, N = m g/cos(50 deg) = 15.256 N (sigma = -1: the
#   mass inside); swinging through the apex of z = (x/a)^2 + (y/b)^2 along x,
#   N = m (g + 2 w^2/a^2) at the apex with w^2 from the energy, and positive
#   throughout although r_u x r_v turns over there; the summary's
#   min / max the same numbers; a mass the surface pulls (the demo slide's,
#   high on the tube's wall near 7.1 s) is named by time and place, with a
#   warning, and none is named where nothing pulls.
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
run() {   # NAME INPUT: its summary in NAME.out, its log in NAME.err
  (cd "$root" && "$slidesim" -o "$work/$1.h5" "$2" >"$work/$1.out" 2>"$work/$1.err") \
    || fail "$1: exit status $? ($(cat "$work/$1.err"))"
}
# the geometry summary names what the slide is
run bowl_slide inputs/parts/bowl_slide.nml
bowl='slide of 4 elements (straight, bowl, straight, runout) with a flume section (centerline length 59.604 m)'
grep -qxF "slidesim geometry: $bowl" "$work/bowl_slide.out" || fail "bowl slide: summary heading: $(head -1 "$work/bowl_slide.out")"
grep -qF "geometry: $bowl" "$work/bowl_slide.err" || fail "bowl slide: log: $(cat "$work/bowl_slide.err")"
run demo_slide inputs/demo_slide/slide.nml
grep -qE "^slidesim geometry: slide of 8 elements \((2 straight|[0-9]+ [a-z]+)(, [0-9]+ [a-z]+)*\) with a circle section \(centerline length [0-9.]+ m\)$" \
  "$work/demo_slide.out" || fail "demo slide: summary heading: $(head -1 "$work/demo_slide.out")"
run helix_tube inputs/geometry/helix_tube.nml
grep -qE "^slidesim geometry: tube surface \(centerline length [0-9.]+ m\)$" "$work/helix_tube.out" \
  || fail "a tube on &centerline: summary heading: $(head -1 "$work/helix_tube.out")"
"$python" - "$work" "$bowl" <<'EOF' || fail "the root attribute surface"
import sys
import h5py
work, bowl = sys.argv[1:3]
with h5py.File(f"{work}/bowl_slide.h5", "r") as f:
    assert f.attrs["surface"] == bowl, f.attrs["surface"]
with h5py.File(f"{work}/demo_slide.h5", "r") as f:
    counted = f.attrs["surface"]
    assert counted.startswith("slide of 8 elements (") and "straight" in counted and "curve" in counted, counted
    kinds = counted.split("(")[1].split(")")[0].split(", ")
    assert sum(int(k.split()[0]) for k in kinds) == 8, counted
print("geometry: the element slides named")
EOF
# the point mass's pressing force against closed forms
run bowl_point_mass inputs/parts/bowl_point_mass.nml
run apex inputs/point_mass/apex_paraboloid.nml
run demo_point_mass inputs/demo_slide/point_mass.nml
run plane inputs/point_mass/plane_coulomb.nml
"$python" - "$work" <<'EOF' || fail "the pressing force"
import re
import sys
import h5py
import numpy as np
work = sys.argv[1]
g = 9.80665

def summary(name):
    text = open(f"{work}/{name}.out").read()
    low, high = re.search(r"normal force min / max +(\S+) / (\S+) N \(> 0 pressing\)", text).groups()
    return float(low), float(high), text

with h5py.File(f"{work}/bowl_point_mass.h5", "r") as f:
    n = f["point_mass/normal_force"][...]
expected = g / np.cos(np.radians(50))
assert np.abs(n - expected).max() < 1e-9 * expected, (n.min(), n.max(), expected)
low, high, text = summary("bowl_point_mass")
assert abs(low - expected) < 1e-4 * expected and abs(high - expected) < 1e-4 * expected, (low, high)
assert "surface pulls" not in text

with h5py.File(f"{work}/apex.h5", "r") as f:
    pm = f["point_mass"]
    n, v, w = pm["normal_force"][...], pm["v"][...], pm["speed"][...]
    z = pm["frame"][...][:, 2, :]
turned = np.flatnonzero(np.einsum("ij,ij->i", z[1:], z[:-1]) < 0)
assert len(turned) >= 4, turned                      # z turns over at each crossing of the apex
assert n.min() > 0, n.min()                          # and the mass presses all the time
a = 1.0                                              # along x (u = 0): z = x^2/a^2, curvature 2/a^2 at the apex
k = np.argmin(np.abs(v))
w0 = np.hypot(0.5 * 1.0, 0.5 * 2 * 0.6)              # du0 = 0, dv0 = -0.5 at v0 = 0.6: |r_v| dv0
w_apex2 = w0**2 + 2 * g * 0.6**2
apex = g + 2 * w_apex2 / a**2
assert abs(w[k]**2 - w_apex2) < 1e-6 * w_apex2, (w[k]**2, w_apex2)
assert abs(v[k]) < 0.01 and abs(n[k] - apex) < 0.02 * apex, (v[k], n[k], apex)   # the record nearest the apex
at_apex = n[k]
low, high, text = summary("apex")
assert abs(low - n.min()) < 1e-4 * abs(low) and abs(high - n.max()) < 1e-4 * high and abs(high - apex) < 1e-3 * apex, \
    (low, high, apex)
assert "surface pulls" not in text

low, high, text = summary("plane")
assert low > 0 and "surface pulls" not in text

with h5py.File(f"{work}/demo_point_mass.h5", "r") as f:
    pm = f["point_mass"]
    n, t, u, v = (pm[k][...] for k in ("normal_force", "time", "u", "v"))
pulled = np.flatnonzero(n < 0)
first = pulled[0]
line = re.search(r"surface pulls the mass +from t = (\S+) to (\S+) s \(u, v = (\S+), (\S+) at its start; (\d+) records",
                 summary("demo_point_mass")[2])
assert line, summary("demo_point_mass")[2]
start, end, u0, v0, count = line.groups()
assert float(start) == round(t[first], 6) and int(count) == len(pulled), (start, t[first], count, len(pulled))
assert abs(float(u0) - u[first]) < 1e-5 * abs(u[first]) and abs(float(v0) - v[first]) < 1e-5, (u0, v0)
assert 7.0 < t[first] < 7.2 and v[first] - np.pi / 2 > 1.9, (t[first], v[first])   # high on the wall
warning = open(f"{work}/demo_point_mass.err").read()
assert f"warning: point_mass: the surface pulls the mass from t = {start} to {end} s" in warning, warning
print(f"bowl: N = {expected:.6f} N; apex: N = {at_apex:.4f} N at the record nearest the apex (closed form {apex:.4f} N), "
      f"z turned over {len(turned)} times; the demo slide's mass pulled from t = {start} s ({len(pulled)} records)")
EOF
echo "new_user_reports: $failures failures"
[ "$failures" = 0 ]
