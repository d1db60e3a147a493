#!/usr/bin/env bash
# --ride-csv FILE: the default ride's time series as CSV beside its summary
# JSON: the header names the columns of docs/outputs.md, one row per record
# of /rider, and its columns equal the result's datasets to its nine digits
# (time, speed, felt g, the pelvis's position, normal forces, wall angles in
# degrees); a ride that may fly adds the column airborne, equal to
# /rider/airborne. Refused: another scenario (exit 1), a device (a private
# /dev/full node: exit 3, nothing run).
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
"$slidesim" -q -o "$work/ride.h5" --summary-json "$work/ride.json" --ride-csv "$work/ride.csv" >"$work/out" 2>&1 \
  || fail "the default ride with --ride-csv: $(cat "$work/out")"
"$python" - "$work/ride.csv" "$work/ride.h5" "$root/docs/outputs.md" <<'PY' || fail "ride.csv against ride.h5"
import sys
import numpy as np, h5py
csv, h5, docs = sys.argv[1:]
header = open(csv).readline().strip().split(',')
table = np.loadtxt(csv, delimiter=',', skiprows=1)
text = open(docs).read().split('## A ride\'s time series as CSV', 1)[1].split('\n## ', 1)[0]
listed = [name.strip() for name in text.split('`time_s', 1)[1].split('` (1', 1)[0].replace('\n', ' ').split(',')]
listed[0] = 'time_s'
bad = []
if header != listed:
    bad.append(f"header {header}, docs {listed}")
with h5py.File(h5) as f:
    deg = 180 / np.pi
    want = {'time_s': f['/rider/time'][()], 'speed_m_per_s': f['/rider/speed'][()],
            'felt_normal_g': f['/rider/acceleration_g'][:, 2], 'pelvis_z_m': f['/rider/pelvis/position'][:, 2],
            'normal_force_heels_N': f['/rider/heels/normal_force'][()],
            'wall_angle_back_deg': f['/rider/back/wall_angle'][()] * deg, 'energy_J': f['/rider/energy'][()]}
if len(table) != len(want['time_s']):
    bad.append(f"{len(table)} rows, /rider has {len(want['time_s'])} records")
else:
    for name, values in want.items():
        column = table[:, header.index(name)]
        # nine significant digits: 1e-8 of the column's largest magnitude
        if np.abs(column - values).max() > 1e-8 * max(1.0, np.abs(values).max()):
            bad.append(f"column {name} differs from the result")
for line in bad:
    print('FAIL ' + line)
sys.exit(1 if bad else 0)
PY
# a ride that may fly (inputs/ride/jump.nml): the column airborne after
# the documented ones, equal to /rider/airborne (the felt values where it is
# not 0 are the model's, not the rider's: the CSV must say where they are)
"$slidesim" -q -o "$work/jump.h5" --ride-csv "$work/jump.csv" "$root/inputs/ride/jump.nml" >"$work/out" 2>&1 \
  || fail "the jump ride with --ride-csv: $(cat "$work/out")"
"$python" - "$work/jump.csv" "$work/jump.h5" "$work/ride.csv" <<'PY' || fail "jump.csv: the column airborne"
import sys
import numpy as np, h5py
csv, h5, plain = sys.argv[1:]
header = open(csv).readline().strip().split(',')
assert header == open(plain).readline().strip().split(',') + ['airborne'], header
table = np.loadtxt(csv, delimiter=',', skiprows=1)
with h5py.File(h5) as f:
    airborne = f['/rider/airborne'][()]
assert len(table) == len(airborne) and np.array_equal(table[:, -1], airborne), 'airborne differs from the result'
assert (airborne == 7).any(), 'the jump has no whole flight'
print(f"jump.csv: airborne on {np.count_nonzero(airborne)} of {len(airborne)} rows")
PY
ls -a "$work" | grep -q '\.tmp' && fail "a temporary file was left"
"$slidesim" -q -o "$work/g.h5" --ride-csv "$work/g.csv" "$root/inputs/geometry/flume.nml" >"$work/out" 2>&1
rc=$?
[ "$rc" = 1 ] && grep -q "has no ride time series" "$work/out" || fail "a geometry run with --ride-csv: exit $rc: $(cat "$work/out")"
[ -e "$work/g.h5" ] && fail "a refused --ride-csv still ran"
if mknod -m 666 "$work/full" c 1 7 2>/dev/null; then
  "$slidesim" -q -o "$work/d.h5" --ride-csv "$work/full" >"$work/out" 2>&1
  rc=$?
  [ "$rc" = 3 ] || fail "--ride-csv onto a device: exit status $rc, not 3"
  [ -c "$work/full" ] || fail "the device node was replaced"
  [ -e "$work/d.h5" ] && fail "a refused --ride-csv still ran"
fi
[ "$failures" = 0 ] && echo "ride CSV checks passed"
[ "$failures" = 0 ]
