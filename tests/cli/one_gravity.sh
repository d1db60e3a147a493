#!/usr/bin/env bash
# One gravity per run (issue 24, point 1): &water gravity and &rider gravity
# are one variable. In a ride (and a sweep, identify_rider) given in one
# group it holds for the water and the rider alike; given in both, the same
# or the run is refused naming file:line, group, variable, value and the
# other group's value and place. Before, the two could disagree: the water
# ran under one gravity and the rider under another.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

# the demo slide, the ride bounded to 2 s so that it takes seconds
ride() {   # NAME WATER_GRAVITY RIDER_GRAVITY ('' for not given)
  {
    echo "&run scenario = 'ride', output = '$1.h5' /"
    echo "&solver duration = 2.0, output_step = 0.05 /"
    echo "&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /"
    echo "&water"
    [ -n "$2" ] && echo "  gravity = $2"
    echo "/"
    echo "&rider"
    [ -n "$3" ] && echo "  gravity = $3"
    echo "/"
  } > "$work/$1.nml"
}
moon_like='0.0, 0.0, -9.5'

# both given and different: refused, nothing written, both places named
ride differ "$moon_like" '0.0, 0.0, -9.80665'
run_case differ 1 'differ.nml:8: &rider: gravity = 0.0, 0.0, -9.80665 is not allowed' \
  'a ride has one gravity' '&water gives gravity = 0.0, 0.0, -9.5 (' 'differ.nml:5)'
# the same by --set: named as the --set argument
ride set_differ "$moon_like" ''
extra_args="--set rider%gravity=0,0,-9.81" run_case set_differ 1 '--set rider%gravity=0,0,-9.81' \
  'a ride has one gravity'
# the sweep and identify_rider read the same (the check runs before any work)
for scenario in sweep identify_rider; do
  sed "s/scenario = 'ride'/scenario = '$scenario'/" "$work/differ.nml" > "$work/differ_$scenario.nml"
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q --check "differ_$scenario.nml" > "differ_$scenario.out" 2> "differ_$scenario.err")
  got=$?
  [ $got = 1 ] || fail "differ_$scenario: exit status $got, expected 1"
  grep -qF 'a ride has one gravity' "$work/differ_$scenario.err" \
    || fail "differ_$scenario: $(head -c 400 "$work/differ_$scenario.err")"
done

# given once, in either group, or the same in both: one ride, the same file
ride in_water "$moon_like" ''
ride in_rider '' "$moon_like"
ride in_both "$moon_like" "$moon_like"
for name in in_water in_rider in_both; do run_case "$name" 0; done
# same_datasets A B GROUP: every dataset of GROUP equal in A and B (the CPU
# times aside); prints the first that differs
same_datasets() {
  "$h5python" - "$@" <<'PY'
import sys, h5py, numpy as np
a, b, group = h5py.File(sys.argv[1], 'r'), h5py.File(sys.argv[2], 'r'), sys.argv[3]
names = []
a[group].visit(lambda n: names.append(n) if isinstance(a[group][n], h5py.Dataset) else None)
for n in names:
    if 'cpu_time' in n:
        continue
    x, y = a[group][n][()], b[group].get(n)
    if y is None or not np.array_equal(np.asarray(x), np.asarray(y[()])):
        sys.exit(f"{group}/{n}")
PY
}
if [ -z "$h5python" ]; then
  fail "no Python with h5py to compare the results"
else
  for name in in_rider in_both; do
    for group in /water /rider /evaluation; do
      checks=$((checks + 1))
      differs=$(same_datasets "$work/in_water.h5" "$work/$name.h5" "$group" 2>&1) \
        || fail "$name: $differs differs from in_water.h5's (one gravity: the same ride)"
    done
  done
  # and it is that gravity, not the standard one, that the ride ran under
  ride standard '' ''
  run_case standard 0
  checks=$((checks + 1))
  same_datasets "$work/in_water.h5" "$work/standard.h5" /rider >/dev/null 2>&1 \
    && fail "in_water: the ride under gravity 9.5 m/s^2 equals the standard one"
fi
finish
