#!/usr/bin/env bash
# The first run installs only what the main job and its plot need: the
# runtime set of scripts/install-dependencies.sh holds no package of the test
# set and no Debian SUNDIALS (CVODE is the project's own build, and Debian's
# libsundials-dev pulls PETSc, hypre, MUMPS and Trilinos); what apt would
# install for it on a bare Debian (simulated: apt-get -s against an empty
# package status) holds none of the test-only packages either; run.sh
# installs the runtime set, check.sh the test set; and this build took
# CVODE's Fortran modules and libraries from the project's build, not from
# Debian's packages. The runtime set is the build set and the plot set, apart;
# the build set brings no Python on a bare Debian (run.sh builds while the plot
# set installs: nothing in the build may wait on it), and run.sh installs the
# build set's packages before it starts the plot set's in the background.
set -u
slidesim=$1
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
script=$root/scripts/install-dependencies.sh

bash "$script" --list runtime >"$work/runtime" || fail "--list runtime: exit status $?"
bash "$script" --list test >"$work/test" || fail "--list test: exit status $?"
bash "$script" --list build >"$work/build" || fail "--list build: exit status $?"
bash "$script" --list plot >"$work/plot" || fail "--list plot: exit status $?"
[ "$(cat "$work/build" "$work/plot")" = "$(cat "$work/runtime")" ] ||
  fail "the runtime list is not the build list and the plot list: $(cat "$work/runtime")"
both=$(sort "$work/build" | comm -12 - <(sort "$work/plot"))
[ -z "$both" ] || fail "in the build and the plot list: $both"
grep -q python "$work/build" && fail "Python in the build list: $(grep python "$work/build")"
[ "$(wc -l <"$work/runtime")" -ge 10 ] || fail "the runtime list is almost empty: $(cat "$work/runtime")"
[ "$(wc -l <"$work/test")" -ge 5 ] || fail "the test list is almost empty: $(cat "$work/test")"
both=$(sort "$work/runtime" | comm -12 - <(sort "$work/test"))
[ -z "$both" ] || fail "in both lists: $both"
# test-only by name: what the tests and viewers use and the build does not
test_only='sundials|paraview|openmpi|mpich|scipy|pint|xarray|h5netcdf|pandas|udunits|hdf5-tools|python3-venv|petsc|hypre|mumps|trilinos'
bad=$(grep -E "$test_only" "$work/runtime")
[ -z "$bad" ] || fail "test-only packages in the runtime list: $bad"
grep -q sundials "$work/test" && fail "Debian's SUNDIALS in the test list: $(grep sundials "$work/test")"
for p in gfortran cmake liblapack-dev minpack-dev libhdf5-dev python3-h5py python3-matplotlib dpkg-dev curl; do
  grep -qx "$p" "$work/runtime" || fail "the runtime list lacks $p"
done
bash "$script" --bogus >/dev/null 2>&1 && fail "--bogus was taken"

# What apt would bring for the runtime set on a bare machine (needs apt's
# package lists: apt-get update, which install-dependencies.sh runs when it
# installs anything)
if apt-cache policy gfortran 2>/dev/null | grep -q 'Candidate: [0-9]'; then
  : >"$work/status"
  mapfile -t runtime <"$work/runtime"
  apt-get install -s -o Dir::State::Status="$work/status" --no-install-recommends "${runtime[@]}" \
    >"$work/apt" 2>&1 || fail "apt-get -s of the runtime set: $(tail -3 "$work/apt")"
  awk '/^Inst /{print $2}' "$work/apt" >"$work/closure"
  n=$(wc -l <"$work/closure")
  [ "$n" -ge 50 ] || fail "apt-get -s gave $n packages: $(tail -3 "$work/apt")"
  bad=$( (grep -E "$test_only" "$work/closure"; sort "$work/closure" | comm -12 - <(sort "$work/test")) | sort -u)
  [ -z "$bad" ] || fail "the runtime set pulls test-only packages: $(echo $bad)"
  mapfile -t build <"$work/build"
  apt-get install -s -o Dir::State::Status="$work/status" --no-install-recommends "${build[@]}" \
    >"$work/apt-build" 2>&1 || fail "apt-get -s of the build set: $(tail -3 "$work/apt-build")"
  bad=$(awk '/^Inst /{print $2}' "$work/apt-build" | grep -E '^(lib)?python' | sort -u)
  [ -z "$bad" ] || fail "the build set pulls Python: $(echo $bad)"
  echo "runtime set on a bare Debian: $n packages, none test-only; the build set brings no Python"
else
  echo "no apt package lists (apt-get update): the runtime set's dependencies not checked"
fi

# run.sh: the build set's packages, then the plot set in the background, then CVODE
order=$(grep -o -E '"\$deps" --(build-packages|plot|build)\b' "$root/scripts/run.sh" | tr '\n' ' ')
[ "$order" = '"$deps" --build-packages "$deps" --plot "$deps" --build ' ] ||
  fail "run.sh does not install the build set, then the plot set, then CVODE: $order"
grep -q 'install-dependencies.sh" --test' "$root/scripts/check.sh" || fail "check.sh does not install the test set"

# CVODE from the project's build (SLIDESIM_SUNDIALS_PREFIX), modules and libraries
cache=$(dirname "$slidesim")/CMakeCache.txt
prefix=$(sed -n 's/^SLIDESIM_SUNDIALS_PREFIX:PATH=//p' "$cache")
modules=$(sed -n 's/^SLIDESIM_SUNDIALS_MODULE_DIR:PATH=//p' "$cache")
[ -n "$prefix" ] && [ -f "$prefix/.complete" ] || fail "no CVODE build at '$prefix' ($cache)"
case $modules in "$prefix"/*) ;; *) fail "fcvode_mod.mod from '$modules', not from $prefix" ;; esac
libraries=$(grep '^SLIDESIM_SUNDIALS_.*:FILEPATH=' "$cache" | sed 's/.*=//')
[ "$(echo "$libraries" | wc -l)" -ge 7 ] || fail "CVODE's libraries not found in $cache"
for lib in $libraries; do
  case $lib in "$prefix"/*) ;; *) fail "CVODE library $lib not from $prefix" ;; esac
done
echo "install lists: $(wc -l <"$work/runtime") runtime, $(wc -l <"$work/test") test packages; $failures failures"
[ "$failures" = 0 ]
