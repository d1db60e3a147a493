#!/usr/bin/env bash
# A flight whose impacts do not close the contact before the run ends (the
# bounces go on to `duration`): the run ends normally (exit 0, the file
# complete) with its impacts table; before, writing the table failed (exit
# 2, "the impact at t = ... has no record of contact 'on_floor' at its
# time": the records of a flight that never closed hold no contact) and the
# file was kept incomplete. A ball dropped from 1 m (its bottom) moving
# sideways at 0.3 m/s, restitution 0.5, for 1 s: impacts at t_1 =
# sqrt(2 h/g) = 0.4516 s and t_2 = t_1 (1 + 2e) = 0.9032 s, each landing
# point on the floor at x = 0.3 t_k (the impact's time located to ~1e-14 s,
# the flight a parabola Adams follows to rounding: 1e-9 m).
set -u
slidesim=$1
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"

cat >"$work/unclosed.nml" <<'NML'
&run scenario = 'contact', output = 'unclosed.h5' /
&solver duration = 1, output_step = 0.01, rtol = 1e-12, atol = 1e-12 /
&shape name = 'floor', kind = 'plane' /
&shape name = 'ball', kind = 'sphere', radius = 0.1 /
&body name = 'ball', mass = 0.2, solid_of = 'ball', position = 0, 0, 1.1, velocity = 0.3, 0, 0 /
&contact name = 'on_floor', shape_1 = 'floor', body_2 = 'ball', shape_2 = 'ball', start = 'open',
  restitution = 0.5, close_speed = 0.1 /
NML
run_case unclosed 0
if [ -n "$h5python" ] && [ -f "$work/unclosed.h5" ]; then
  "$h5python" - "$work/unclosed.h5" <<'PY' || fail "unclosed: the impacts table"
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], 'r')
table = f['contact/impacts']
t1 = np.sqrt(2 * 1.0 / 9.80665)
times = np.array([t1, t1 * (1 + 2 * 0.5)])
ok = table['time'].shape == (2,) and np.allclose(table['time'][:], times, rtol=0, atol=1e-9)
position = table['position'][:]
ok = ok and position.shape == (2, 3)
ok = ok and np.allclose(position[:, 0], 0.3 * times, rtol=0, atol=1e-9)
ok = ok and np.allclose(position[:, 1:], 0, rtol=0, atol=1e-9)
if not ok:
    print('times', table['time'][:], 'expected', times, 'positions', position)
sys.exit(0 if ok else 1)
PY
fi
finish
