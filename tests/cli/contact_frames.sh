#!/usr/bin/env bash
# Frames in result files as h5py reads them (issue 27, point 7): a body's
# /contact/bodies/<b>/rotation and the point mass's /point_mass/frame hold one
# axis per ROW (rotation[i, k, :] is axis k in world coordinates), as
# docs/outputs.md, the datasets' descriptions and python/slidesim/plot/egg.py say.
# Checked against a known rotation (a ball at rest on the table, angles_deg =
# 30, 20, 10: axes = the columns of Rx Ry Rz) and against the normal of an
# ellipsoid (the point mass's z axis along the gradient of x^2/a^2 + ...,
# perpendicular to its velocity). Before: the docs said columns.
set -u
slidesim=$1
root=$(pwd)
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"
[ -n "$h5python" ] || { echo "SKIP: no python3 with h5py"; exit 0; }

cat > "$work/frames.nml" <<'NML'
&run scenario = 'contact', output = 'frames.h5' /
&solver duration = 0.01, output_step = 0.01 /
&shape name = 'table', kind = 'plane' /
&shape name = 'ball', kind = 'ellipsoid', a = 0.1, b = 0.1, c = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball',
  position = 0, 0, 0.1, angles_deg = 30, 20, 10 /
&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /
NML
run_case frames 0
sed -e "s|output = .*|output = 'mass.h5'|" -e 's/duration = 10.0/duration = 0.5/' \
  "$root/inputs/point_mass/ellipsoid.nml" > "$work/mass.nml"
run_case mass 0

checks=$((checks + 1))
out=$("$h5python" - "$work/frames.h5" "$work/mass.h5" "$root/docs/outputs.md" <<'PY'
import sys
import h5py
import numpy as np

bad = []
a, b, c = np.radians([30.0, 20.0, 10.0])
rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
ry = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
rz = np.array([[np.cos(c), -np.sin(c), 0], [np.sin(c), np.cos(c), 0], [0, 0, 1]])
axes = rx @ ry @ rz                      # body axis k = column k (docs/contact.md, angles_deg)
with h5py.File(sys.argv[1]) as f:
    d = f["contact/bodies/ball/rotation"]
    for k in range(3):                   # at rest: every sample; 1e-12: rounding of the angles
        err = np.abs(d[:, k, :] - axes[:, k]).max()
        if err > 1e-12:
            bad.append(f"rotation[:, {k}, :] is not body axis {k}: off by {err:.3g}")
    if "rotation[i, k, :] is body axis k" not in d.attrs["description"]:
        bad.append(f"rotation's description does not say rows: {d.attrs['description']!r}")
with h5py.File(sys.argv[2]) as f:
    frame = f["point_mass/frame"][...]
    r = f["point_mass/position"][...]
    v = f["point_mass/velocity"][...]
    normal = r / np.array([2.0, 1.5, 1.0]) ** 2          # the ellipsoid's gradient (semi-axes of the input)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    # 1e-9: the mass stays on the surface to the integrator's tolerance
    cross = np.abs(np.cross(frame[:, 2, :], normal)).max()
    along = np.abs(np.einsum("ij,ij->i", frame[:, 2, :], v)).max() / np.abs(v).max()
    if cross > 1e-9 or along > 1e-9:
        bad.append(f"frame[:, 2, :] is not the normal (x gradient {cross:.3g}, . velocity {along:.3g})")
    if "frame[i, k, :] is axis k" not in f["point_mass/frame"].attrs["description"]:
        bad.append("frame's description does not say rows")
docs = open(sys.argv[3]).read()
for needle in ("`rotation[i, k, :]` is body axis k", "`frame[i, 2, :]` z axis"):
    if needle not in docs:
        bad.append(f"docs/outputs.md lacks {needle!r}")
print("\n".join(bad))
PY
) || fail "frames check: $out"
[ -z "$out" ] || fail "$out"
grep -qF 'rot[i, k, :] = body axis k' "$root/python/slidesim/plot/egg.py" || \
  fail "python/slidesim/plot/egg.py does not read the axes as rows"

finish
