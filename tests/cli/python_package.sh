#!/usr/bin/env bash
# The Python package (python/) installs with pip into a fresh virtual
# environment and works from there, outside the repository: slidesim.open on
# the results of every input (tests/cli/check_python_package.py), every plot
# through the installed slidesim-plot command (one result per scenario, the
# egg's comparison of two files) and python -m slidesim.plot, pictures that
# are PNGs of some size; a file of another scenario for --kind refused (exit
# 1). The scripts in scripts/ are executable, and one run by a Python without
# the modules says which package to install (exit 1).
#
# Offline by default: the venv sees Debian's python3-numpy, -h5py, -xarray,
# -pandas and -matplotlib (--system-site-packages) and pip installs only the
# package (--no-index --no-deps --no-build-isolation: Debian's setuptools
# builds it; Debian's h5py is not registered under the name h5py, so pip
# would not take it for the dependency). SLIDESIM_PYTHON_FROM_PYPI=1 makes a
# venv without the system's packages and lets pip fetch setuptools, numpy,
# h5py, xarray, pandas, matplotlib and their dependencies from PyPI (~60 MB).
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

cp -r "$root/python" "$work/source"   # a copy: pip builds in place (build/, *.egg-info)
if [ "${SLIDESIM_PYTHON_FROM_PYPI:-0}" = 1 ]; then
  "$python" -m venv "$work/venv" || fail "python3 -m venv"
  "$work/venv/bin/pip" install -q "$work/source" >"$work/pip.log" 2>&1 || fail "pip install from PyPI: $(tail -5 "$work/pip.log")"
else
  "$python" -m venv --system-site-packages "$work/venv" || fail "python3 -m venv --system-site-packages"
  "$work/venv/bin/pip" install -q --no-index --no-deps --no-build-isolation "$work/source" >"$work/pip.log" 2>&1 \
    || fail "pip install ./python: $(tail -5 "$work/pip.log")"
fi
venv=$work/venv/bin
mkdir "$work/out"
cd "$work/out"   # not the repository: the installed package, not python/

"$venv/python" "$root/tests/cli/check_python_package.py" "$results" "$root/README.md" "$root/CMakeLists.txt" \
  || fail "slidesim.open on every result"

# every plot from the installed command, one result of each scenario
plots=0
picture() {   # NAME: the PNG written is one, and not almost empty
  if [ "$(head -c 8 "$1" 2>/dev/null | od -An -c | tr -d ' ')" != '211PNG\r\n032\n' ]; then
    fail "$1 is not a PNG"
  elif [ "$(stat -c %s "$1")" -lt 20000 ]; then
    fail "$1 is almost empty ($(stat -c %s "$1") bytes)"
  else
    plots=$((plots + 1))
  fi
}
for name in ride_demo_slide water_demo_slide geometry_flume point_mass_ellipsoid pendulum_double \
            fourbar_crank_rocker sled_bowl contact_egg design_optimize_table_4_12 design_identify_rider_demo \
            design_identify_water_demo sweep_demo_population design_optimize_standard_parts; do
  "$venv/slidesim-plot" "$results/$name.h5" -o "$work/out/$name.png" >"$work/$name.log" 2>&1 \
    || fail "slidesim-plot $name.h5: $(tail -3 "$work/$name.log")"
  picture "$work/out/$name.png"
done
"$venv/slidesim-plot" --kind egg "$results/contact_egg.h5" "$results/contact_egg_long_axis_z.h5" -o "$work/out/egg.png" \
  >"$work/egg.log" 2>&1 || fail "slidesim-plot --kind egg: $(tail -3 "$work/egg.log")"
picture "$work/out/egg.png"
"$venv/slidesim-plot" "$results/sweep_demo_population.h5" --x flow_rate -o "$work/out/sweep_flow.png" \
  >"$work/sweep.log" 2>&1 || fail "slidesim-plot --x flow_rate: $(tail -3 "$work/sweep.log")"
picture "$work/out/sweep_flow.png"
cp "$results/ride_demo_slide.h5" "$work/out/ride.h5"
"$venv/python" -m slidesim.plot ride.h5 >"$work/m.log" 2>&1 || fail "python -m slidesim.plot: $(tail -3 "$work/m.log")"
grep -q "wrote ride.png" "$work/m.log" || fail "python -m slidesim.plot said: $(cat "$work/m.log")"
picture "$work/out/ride.png"

# refusals: another scenario for --kind, a file that is not a result
"$venv/slidesim-plot" --kind ride "$results/water_demo_slide.h5" -o "$work/wrong.png" >"$work/wrong.log" 2>&1
status=$?
[ "$status" = 1 ] && grep -q "water_demo_slide.h5: a 'water' result, but this needs a result of 'ride'" "$work/wrong.log" \
  || fail "--kind ride on a water result: status $status: $(cat "$work/wrong.log")"
[ ! -e "$work/wrong.png" ] || fail "--kind ride on a water result wrote a picture"
"$venv/slidesim-plot" "$root/README.md" >"$work/text.log" 2>&1
status=$?
[ "$status" = 1 ] && grep -q "README.md: not an HDF5 file" "$work/text.log" || fail "a text file: status $status: $(cat "$work/text.log")"

# the scripts: executable, and a Python without the modules is told what to install
for script in "$root"/scripts/plot*.py; do
  [ -x "$script" ] || fail "$script is not executable"
done
if [ -d "$root/.git" ] || [ -f "$root/.git" ]; then
  modes=$(git -C "$root" ls-files -s -- 'scripts/plot*.py' | awk '$1 != "100755" {print $4}')
  [ -z "$modes" ] || fail "not mode 100755 in git: $modes"
fi
"$python" -m venv --without-pip "$work/bare" || fail "python3 -m venv --without-pip"
"$work/bare/bin/python" "$root/scripts/plot_ride.py" ride.h5 >"$work/bare.log" 2>&1
status=$?
[ "$status" = 1 ] && grep -q "the Python module '[a-z0-9]*' is missing" "$work/bare.log" \
  && grep -q "apt-get install python3-" "$work/bare.log" && grep -q "pip install ./python" "$work/bare.log" \
  && ! grep -q Traceback "$work/bare.log" || fail "a Python without the modules: status $status: $(cat "$work/bare.log")"
"$work/bare/bin/python" -c "import sys; sys.path.insert(0, '$root/python'); import slidesim
try:
    slidesim.open('ride.h5')
except ImportError as error:
    print(type(error).__name__, error)" >"$work/bare.log" 2>&1
grep -q "MissingModule the Python module 'h5py' is missing" "$work/bare.log" \
  || fail "slidesim.open without h5py: $(cat "$work/bare.log")"

echo "python package: $plots plots, $failures failures"
[ "$failures" = 0 ]
