#!/usr/bin/env bash
# The mat over the jump thrown fast (inputs/parts/mat_jump.nml with
# du0 = 9 m/s; docs/vehicles.md "Flight"): the whole mat flies 0.54 s and
# lands front first on the run-out at 6.33 m/s (plastic); the front then
# pulls (its normal force -228 N with the landing's velocity jump: the mat
# turns fast about it) and flies on from the slide, its gap rising from 0
# as the watch expects. The rear, 0.54 m above the bottom of the tube of
# radius 0.5 m, falls through the tube's axis: a centre of curvature of
# the slide, where an open contact's coordinates (its foot point and its
# lift along the normal there) are singular. That is not built: the run
# ends part way (exit 2, the file kept and marked) and says so. Before
# (main ad54086) the same exit 2 blamed stiffness ("use method = 'bdf'",
# which fails the same), so this test failed there.
# Checked: the message names the true cause and gives no bdf advice; the
# landing's report (drop height v_n^2/(2 g) of its normal speed); the
# energy of the whole mat in each flight (both contacts open: dry, no
# friction, no air drag) stays its value at the flight's start to 1e-8 of
# the largest kinetic energy there (rtol 1e-10 per step over ~0.5 s: seen
# 3.3e-9 in Debug, 7.8e-9 in Release, the bound's nearest; a missing force
# or term would be O(1): gravity alone adds
# 1400 J of kinetic energy in the first flight, 5661 -> 7061 J).
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
(cd "$root" && "$slidesim" --set sled%du0=9 -o "$work/fast.h5" inputs/parts/mat_jump.nml \
  >"$work/fast.out" 2>"$work/fast.err"); got=$?
check '[ $got = 2 ]' "exit status $got, expected 2: $(cat "$work/fast.err")"
check 'grep -q "the rear contact.s end flies .* m from a centre of curvature of the surface below it (its lift 0.50" "$work/fast.err"' \
  "the message lacks the centre of curvature: $(cat "$work/fast.err")"
check '! grep -q "use method = .bdf." "$work/fast.err"' "the message advises bdf: $(cat "$work/fast.err")"
check 'grep -q "results (INCOMPLETE)" "$work/fast.out" && [ -f "$work/fast.h5" ]' "the incomplete file is not kept"
check 'grep -q "landing 1 (front) .*normal speed 6.33.* m/s, .*drop height 2.04.* m, flew on" "$work/fast.out"' \
  "the front's landing: $(grep landing "$work/fast.out")"
out=$("$py" - "$work/fast.h5" <<'PY' 2>&1
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
s = f["sled"]
t, e, k = s["time"][:], s["energy"][:], s["kinetic_energy"][:]
open_ = s["vehicle/open"][:]
g = 9.80665  # the standard gravity (base_constants), the input sets none
# the landing's drop height is its normal speed's v^2/(2 g)
land = s["vehicle/flight/landing"]
bad = []
for name in ("normal_speed", "drop_height"):
    if name not in land:
        bad.append(f"no landing/{name}")
if not bad:
    v, h = land["normal_speed"][:], land["drop_height"][:]
    if len(v) != 1 or abs(h[0] - v[0] ** 2 / (2 * g)) > 1e-12 * h[0]:
        bad.append(f"landings {len(v)}, drop height {h} against v^2/(2g) {v ** 2 / (2 * g)}")
# each stretch of records with both contacts open (a switch is two records
# at one time: a stretch starts at the second)
starts = [i for i in range(len(t)) if open_[i] == 3 and (i == 0 or open_[i - 1] != 3 or t[i] == t[i - 1])]
stretches = []
for i0 in starts:
    i1 = i0
    while i1 + 1 < len(t) and open_[i1 + 1] == 3 and t[i1 + 1] != t[i1]:
        i1 += 1
    stretches.append((i0, i1))
if len(stretches) != 2:
    bad.append(f"{len(stretches)} whole flights, expected 2 (the jump, the front's flying on): {stretches}")
for i0, i1 in stretches:
    drift = np.max(np.abs(e[i0:i1 + 1] - e[i0]))
    scale = np.max(k[i0:i1 + 1])
    print(f"flight {t[i0]:.6f}..{t[i1]:.6f} s: energy drift {drift:.3e} J of kinetic {scale:.1f} J")
    if not drift <= 1e-8 * scale:
        bad.append(f"the flight from t = {t[i0]} s: energy drifts {drift} J, more than 1e-8 of {scale} J")
if bad:
    print("; ".join(bad))
    sys.exit(1)
PY
); pyrc=$?
check '[ $pyrc = 0 ]' "the flights' energy and the landing: $out"
echo "$out"
echo "mat_jump_fast: $checks checks, $failures failed"
[ "$failures" = 0 ]
