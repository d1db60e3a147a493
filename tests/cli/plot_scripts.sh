#!/usr/bin/env bash
# Every plot script (a thin call of the package python/slidesim) runs
# headless on a result of its scenario and writes a PNG (-o); each refuses a result of another scenario and a file that is not a
# result with a message naming the file (exit status 1). The results come from
# the fixture cli_every_input (tests/cli/support/every_input.sh). Needs
# Debian's python3-matplotlib, -h5py, -numpy (scripts/install-dependencies.sh).
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
(cd "$root" && "$slidesim" -q -o "$work/slide.h5" inputs/demo_slide/slide.nml >/dev/null 2>&1) || fail "slidesim slide.nml"
link() { ln -s "$results/$2.h5" "$work/$1.h5"; }
link water water_demo_slide
link point_mass point_mass_ellipsoid
link pendulum pendulum_double
link fourbar fourbar_crank_rocker
link sled sled_bowl
link ride ride_demo_slide
link contact contact_egg
link egg contact_egg
link optimization design_optimize_table_4_12
link identify_rider design_identify_rider_demo
link identify_water design_identify_water_demo
link sweep sweep_demo_population
"$python" "$root/tests/cli/check_plot_scripts.py" "$root/scripts" "$work" "$work/water.h5" "$work/sled.h5" \
  "$root/README.md" water=water slide=geometry point_mass=point_mass pendulum=pendulum fourbar=fourbar sled=sled \
  ride=ride contact=contact egg=contact optimization=optimize identify_rider=identify_rider \
  identify_water=identify_water sweep=sweep || fail "plot scripts"
# scripts/plot.py picks the plot by the scenario: the ride's for a ride
"$root/scripts/plot.py" "$work/ride.h5" -o "$work/any.png" >"$work/any.log" 2>&1 || fail "plot.py: $(cat "$work/any.log")"
cmp -s <(head -c 8 "$work/any.png") <(printf '\211PNG\r\n\032\n') || fail "plot.py wrote no PNG"
"$root/scripts/plot.py" "$root/README.md" >"$work/any.log" 2>&1
[ $? = 1 ] && grep -q "README.md: not an HDF5 file" "$work/any.log" || fail "plot.py on a text file: $(cat "$work/any.log")"
# the egg plot's tilt is the symmetry axis's: the egg described with its long
# axis on z (a chart change as it stands up) draws the shipped egg's curve
"$python" - "$root/python" "$results/contact_egg.h5" "$results/contact_egg_long_axis_z.h5" <<'PY' || fail "plot_egg: the long axis on z"
import json
import sys
sys.path.insert(0, sys.argv[1])
import h5py
import numpy as np
from slidesim.plot import egg as plot_egg
theta = []
for path in sys.argv[2:]:
    with h5py.File(path, "r") as f:
        text = f["/input/namelist"].asstr()[()]
        mu, a, b, g, axis = plot_egg.egg_parameters(text)
        theta.append((axis, f["contact/time"][...], plot_egg.tilt(f, axis)))
(axis_y, t_y, theta_y), (axis_z, t_z, theta_z) = theta
common, i_y, i_z = np.intersect1d(t_y, t_z, return_indices=True)   # the z egg has a record at its chart change
worst = np.abs(theta_y[i_y] - theta_z[i_z]).max()
assert (axis_y, axis_z) == (1, 2), (axis_y, axis_z)
assert len(common) == len(t_y) and len(t_y) > 100 and worst < 1e-6, (len(common), len(t_y), worst)
# the summary counts the chart change (the shipped egg has none)
with open(sys.argv[3].replace(".h5", ".json")) as f:
    text = f.read()
assert '"chart_changes": 1,' in text, text[:400]
with open(sys.argv[2].replace(".h5", ".json")) as f:
    assert "chart_changes" not in f.read()
print(f"plot_egg: long axis on z against the shipped egg, theta within {worst:.1e} degrees")
PY
# a failed run's long message stays on the picture: the title in at most 3
# lines of 130 characters (a sled stopped by max_steps at t = 0.0078 s, early
# enough to fail alike in Release and Debug builds: its message runs to 220)
(cd "$work" && "$slidesim" -q -o failed_sled.h5 --set solver%max_steps=5 "$root/inputs/parts/mat.nml" >/dev/null 2>&1)
[ $? = 2 ] || fail "the mat with max_steps = 5 did not fail part way (exit 2)"
"$python" - "$root/python" "$work/failed_sled.h5" "$work/failed_sled.png" <<'PY' || fail "the failed sled's title"
import sys
sys.path.insert(0, sys.argv[1])
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from slidesim.plot import main
assert main(["--kind", "sled", sys.argv[2], "-o", sys.argv[3]]) == 0
text = plt.gcf()._suptitle.get_text()
lines = text.split("\n")
assert "INCOMPLETE: sled: more than max_steps = 5" in text, text
assert 1 < len(lines) <= 3 and max(map(len, lines)) <= 130, lines
print(f"the failed sled's title in {len(lines)} lines")
PY
echo "13 plot scripts and plot.py, $failures failures"
[ "$failures" = 0 ]
