#!/usr/bin/env bash
# Issue 26's check "every shipped input in inputs/parts/ runs and is
# plotted": every inputs/parts/*.nml has a complete result in the fixture
# cli_every_input (tests/cli/support/every_input.sh, exit status 0), and
# scripts/plot.py (the plot of its scenario: plot_slide, plot_ride,
# plot_sled, plot_point_mass) draws each headless into a PNG, exit status 0.
# The ride's plot draws its unrolled slide as the distance along the wall
# from the bottom: its contacts' lines are their /rider/<c>/wall_distance
# (not the wall angle, which stays at 90 deg on a flume's wall), and the
# water band's middle is the table's v measured along the section, which
# matches the pelvis's own wall distance where the pelvis is in the water's
# middle; a vehicle's plot has the same panel from
# /sled/vehicle/<contact>/wall_distance. A point mass circling in a bowl at
# constant speed has its speed and normal force drawn flat.
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
unset DISPLAY   # as in CI: no window, the Agg backend
. "$root/tests/cli/support/every_input_results.sh"   # sets $results
count=0
for input in "$root"/inputs/parts/*.nml; do
  name=parts_$(basename "$input" .nml)
  count=$((count + 1))
  [ -f "$results/$name.rc" ] || { fail "$name: not run by the fixture cli_every_input"; continue; }
  [ "$(cat "$results/$name.rc")" = 0 ] || { fail "$name: exit status $(cat "$results/$name.rc")"; continue; }
  "$python" "$root/scripts/plot.py" "$results/$name.h5" -o "$work/$name.png" >"$work/$name.log" 2>&1 \
    || { fail "$name: plot.py: $(cat "$work/$name.log")"; continue; }
  cmp -s <(head -c 8 "$work/$name.png") <(printf '\211PNG\r\n\032\n') || fail "$name: no PNG written"
done
[ "$count" -ge 23 ] || fail "only $count inputs in inputs/parts"
# what the unrolled panels draw (a ride on the half-pipe, the ring on it)
"$python" - "$root/python" "$results/parts_halfpipe.h5" "$results/parts_ring.h5" "$results/parts_bowl_point_mass.h5" \
  >"$work/panels.out" 2>&1 <<'EOF' \
  || fail "the unrolled panels: $(cat "$work/panels.out")"
import sys
sys.path.insert(0, sys.argv[1])
import matplotlib
matplotlib.use("Agg")
import h5py
import numpy as np
from slidesim.plot import figure

ride, sled, circling = sys.argv[2:5]
fig = figure(ride)
ax = fig.axes[0]
assert "distance along the wall" in ax.get_ylabel(), ax.get_ylabel()
lines = {l.get_label(): l for l in ax.lines}
with h5py.File(ride, "r") as f:
    for c in ("pelvis", "heels", "back"):
        x, y = lines[c].get_data()
        assert np.array_equal(x, f[f"rider/{c}/arc_length"][...]), c
        assert np.array_equal(y, f[f"rider/{c}/wall_distance"][...]), c
    # the water's middle along the section against the pelvis's own
    # distance where the pelvis rides at the water's v (the table's u)
    x, y = lines["water middle"].get_data()
    table = f["water/table"]
    pelvis_v = np.interp(table["u"][...], f["rider/pelvis/u"][...], f["rider/pelvis/v"][...])
    pelvis_d = np.interp(table["u"][...], f["rider/pelvis/u"][...], f["rider/pelvis/wall_distance"][...])
    near = np.abs(pelvis_v - table["v"][...]) < 2e-4   # within 4e-4 m of each other on the 2 m circle
    assert near.sum() > 3, near.sum()
    worst = np.abs(y[near] - pelvis_d[near]).max()
    assert worst < 1e-3, worst   # + the surface grid's chords (48 across the flume): 3e-4 m measured
    print(f"ride: contacts' wall distance drawn; the water's middle within {worst:.1e} m of the pelvis's")
fig = figure(sled)
panels = [a for a in fig.axes if "distance along the wall" in a.get_ylabel()]
assert len(panels) == 1, [a.get_ylabel() for a in fig.axes]
with h5py.File(sled, "r") as f:
    drawn = [l for l in panels[0].lines if not l.get_label().startswith("_")]
    assert len(drawn) == 2, [l.get_label() for l in drawn]
    for l in drawn:
        c = l.get_label().split()[0]
        assert np.array_equal(l.get_ydata(), f[f"sled/vehicle/{c}/wall_distance"][...]), c
    print("sled: the contacts' wall distance drawn")
# a point mass circling in a bowl at constant speed: its speed and normal
# force drawn flat, not a spread of 1e-12 stretched over the axis against
# an offset (which read as a speed falling from 8 to 4 m/s)
fig = figure(circling)
fig.canvas.draw()
with h5py.File(circling, "r") as f:
    for name in ("speed", "normal_force"):
        values = f[f"point_mass/{name}"][...]
        ax = [a for a in fig.axes if a.get_ylabel().startswith(name.replace("_", " "))][0]
        low, high = ax.get_ylim()
        assert np.ptp(values) < 1e-9 * np.abs(values).max(), (name, np.ptp(values))
        assert high - low > 1e-3 * np.abs(values).max(), (name, low, high)
        assert ax.yaxis.get_offset_text().get_text() == "", (name, ax.yaxis.get_offset_text().get_text())
        assert ax.get_legend().get_texts()[0].get_text().startswith("constant to "), name
    print("point mass: speed and normal force drawn flat")
EOF
echo "$count inputs of inputs/parts run and plotted, $failures failures"
[ "$failures" = 0 ]
