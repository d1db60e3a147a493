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
# constant speed has its speed and normal force drawn flat. A vehicle that
# flies (mat_jump) has its flights shaded and its landings marked on every
# plot over time, from /sled/vehicle/open and its landing table, and its
# wall panel (the mat on the bottom line: rounding noise) drawn flat. Every
# title of a slide's picture lies inside the picture.
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
  "$results/parts_mat_jump.h5" >"$work/panels.out" 2>&1 <<'EOF' \
  || fail "the unrolled panels: $(cat "$work/panels.out")"
import sys
sys.path.insert(0, sys.argv[1])
import matplotlib
matplotlib.use("Agg")
import h5py
import numpy as np
from slidesim.plot import figure

ride, sled, circling, jump = sys.argv[2:6]
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
# a vehicle that flies (mat_jump): every plot over time shades its flights
# (a contact open; both open darker) from /sled/vehicle/open and draws each
# landing at /sled/vehicle/flight/landing/time; its wall panel, the mat on
# the bottom line (1e-15 m of rounding), spans at least 1 cm either side
fig = figure(jump)
fig.canvas.draw()
with h5py.File(jump, "r") as f:
    t = f["sled/time"][...]
    is_open = f["sled/vehicle/open"][...]
    landings = f["sled/vehicle/flight/landing/time"][...]
    wall = np.concatenate([f[f"sled/vehicle/{c}/wall_distance"][...] for c in ("rear", "front")])
def runs(flying):
    edges = np.flatnonzero(np.diff(np.concatenate([[0], flying.astype(int), [0]])))
    return [(t[a], t[min(b, len(t) - 1)]) for a, b in zip(edges[::2], edges[1::2])]
expected = {"flight": runs(is_open != 0), "whole_flight": runs(is_open == 3)}
assert len(expected["flight"]) >= 1 and len(expected["whole_flight"]) >= 1 and len(landings) >= 2, \
    (expected, landings)
over_time = [a for a in fig.axes if a.get_xlabel() == "time [s]"]
assert len(over_time) == 5, [a.get_title() for a in fig.axes]
for a in over_time:
    for gid, spans in expected.items():
        drawn = sorted((min(p.get_xy()[:, 0]), max(p.get_xy()[:, 0])) for p in a.patches if p.get_gid() == gid)
        assert np.allclose(drawn, spans, rtol=0, atol=1e-12), (a.get_title(), gid, drawn, spans)
    lines = sorted(l.get_xdata()[0] for l in a.lines if l.get_gid() == "landing")
    assert np.allclose(lines, np.sort(landings), rtol=0, atol=1e-12), (a.get_title(), lines, landings)
assert np.abs(wall).max() < 1e-9, np.abs(wall).max()
panel = [a for a in fig.axes if "distance along the wall" in a.get_ylabel()][0]
low, high = panel.get_ylim()
assert low <= -0.01 and high >= 0.01, (low, high)
assert panel.yaxis.get_offset_text().get_text() == "", panel.yaxis.get_offset_text().get_text()
print(f"mat_jump: {len(expected['flight'])} flight(s), {len(landings)} landings marked on {len(over_time)} plots; "
      "the wall panel flat")
EOF
# every title of a slide's picture inside the picture (the 3-D panel's title,
# the slide's description, ran off its left edge in one line for a chain of
# six elements: bowl_halfpipe_slide)
"$python" - "$root/python" "$results"/parts_*_slide.h5 >"$work/titles.out" 2>&1 <<'EOF' \
  || fail "the slides' titles: $(cat "$work/titles.out")"
import sys
sys.path.insert(0, sys.argv[1])
import matplotlib
matplotlib.use("Agg")
from slidesim.plot import figure

assert len(sys.argv) > 6, sys.argv
for name in sys.argv[2:]:
    fig = figure(name)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    width, height = fig.canvas.get_width_height()
    texts = [a.title for a in fig.axes] + [t for t in fig.texts]
    for text in texts:
        if not text.get_text():
            continue
        box = text.get_window_extent(renderer)
        assert box.x0 >= 0 and box.x1 <= width and box.y1 <= height, (name, text.get_text(), box, width)
    print(f"{name}: {len(texts)} titles inside the picture")
EOF
echo "$count inputs of inputs/parts run and plotted, $failures failures"
[ "$failures" = 0 ]
