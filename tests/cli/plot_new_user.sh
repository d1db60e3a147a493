#!/usr/bin/env bash
# What a new user met in the plots (closing note 14, "Noticed and left alone"):
# - the water plot (scripts/plot_water.py, slidesim-plot --kind water) draws
#   the /water group of ANY result that holds one: every result of the
#   fixture cli_every_input with /water (rides, sleds in water, water runs)
#   is drawn, its streamline the file's own /water/arc_length and angle from
#   the bottom; a result without /water (a sled riding dry) is refused with
#   exit status 1 and a message naming the file and why;
# - the sled plot's coordinates: one y axis per unit, so a length (u, m)
#   never shares a scale with an angle (phi, deg); each axis is labelled
#   with its coordinates and unit, and every coordinate is drawn once with
#   its own values (angles in degrees).
# The results come from the fixture cli_every_input (tests/cli/support/every_input.sh).
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
# the command: a sled in water drawn, a dry sled refused naming the file
"$python" "$root/scripts/plot_water.py" "$results/parts_ring.h5" -o "$work/ring.png" >"$work/ring.log" 2>&1 \
  || fail "plot_water.py on a sled in water: $(cat "$work/ring.log")"
cmp -s <(head -c 8 "$work/ring.png") <(printf '\211PNG\r\n\032\n') || fail "plot_water.py wrote no PNG of the ring"
"$python" "$root/scripts/plot_water.py" "$results/sled_bowl.h5" -o "$work/dry.png" >"$work/dry.log" 2>&1
got=$?
[ $got = 1 ] || fail "plot_water.py on a dry sled: exit status $got, expected 1"
grep -qF "error: $results/sled_bowl.h5: a 'sled' result, which holds no water (no group /water)" "$work/dry.log" \
  || fail "plot_water.py on a dry sled: $(cat "$work/dry.log")"
[ ! -e "$work/dry.png" ] || fail "plot_water.py wrote a picture of a dry sled"
"$python" - "$root/python" "$results" >"$work/panels.out" 2>&1 <<'EOF' || fail "the panels: $(cat "$work/panels.out")"
import glob
import os
import sys
sys.path.insert(0, sys.argv[1])
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import h5py
import numpy as np
from slidesim.plot import figure
from slidesim.results import ResultFileError

results = sys.argv[2]
DEGREES = 180 / np.pi
drawn, refused = {}, 0
for path in sorted(glob.glob(os.path.join(results, "*.h5"))):
    with h5py.File(path, "r") as f:
        scenario = f.attrs["scenario"]
        scenario = scenario.decode() if isinstance(scenario, bytes) else scenario
        water = "water" in f and "arc_length" in f["water"]
        if water:
            s, v = f["water/arc_length"][...], f["water/v"][...]
    if not water:
        if scenario in ("ride", "sled"):   # these may ride dry: refused, naming the file
            try:
                figure(path, "water")
                raise AssertionError(f"{path}: a {scenario} result without /water drawn")
            except ResultFileError as error:
                assert str(error).startswith(f"{path}: a '{scenario}' result, which holds no water"), error
                refused += 1
        continue
    if scenario == "water" and drawn.get("water", 0) >= 2:
        continue   # the water runs have tests of their own (plot_scripts)
    fig = figure(path, "water")
    line = [l for l in fig.axes[0].lines if l.get_label() == "streamline (middle)"][0]
    x, y = line.get_data()
    assert np.array_equal(x, s) and np.allclose(y, (v - np.pi / 2) * DEGREES, rtol=0, atol=1e-12), path
    drawn[scenario] = drawn.get(scenario, 0) + 1
    plt.close(fig)
assert drawn.get("ride", 0) >= 3 and drawn.get("sled", 0) >= 2 and refused >= 2, (drawn, refused)
print(f"water plot: drawn {drawn}, {refused} results without water refused")

# the sled's coordinates: one axis per unit, each labelled, each coordinate once
for name in ("sled_bowl", "parts_ring", "parts_mat"):
    path = os.path.join(results, name + ".h5")
    fig = figure(path)
    with h5py.File(path, "r") as f:
        units = {q: f[f"sled/coordinates/{q}/value"].attrs["units"] for q in f["sled/coordinates"]}
        units = {q: (u.decode() if isinstance(u, bytes) else u) for q, u in units.items()}
        axes = [a for a in fig.axes if any(l.get_label().split(" [")[0] in units for l in a.lines)]
        seen = []
        for ax in axes:
            shown = {l.get_label().split(" [")[0]: l for l in ax.lines if l.get_label().split(" [")[0] in units}
            axis_units = {"deg" if units[q] == "rad" else units[q] for q in shown}
            assert len(axis_units) == 1, (name, ax.get_ylabel(), axis_units)
            unit = axis_units.pop()
            assert ax.get_ylabel() == f"{', '.join(sorted(shown))} [{unit}]", (name, ax.get_ylabel())
            for q, line in shown.items():
                scale = DEGREES if units[q] == "rad" else 1.0
                assert np.array_equal(line.get_ydata(), f[f"sled/coordinates/{q}/value"][...] * scale), (name, q)
            seen += shown
        assert sorted(seen) == sorted(units), (name, seen, units)
        assert len(axes) == len({"deg" if u == "rad" else u for u in units.values()}), (name, len(axes))
    plt.close(fig)
    print(f"{name}: coordinates on {len(axes)} axes: {[a.get_ylabel() for a in axes]}")
EOF
cat "$work/panels.out"
echo "plot_new_user: $failures failures"
[ "$failures" = 0 ]
