#!/usr/bin/env bash
# A flying vehicle's highest point above the slide (docs/vehicles.md
# "Flight", "Highest point"): inputs/parts/mat_jump.nml, the mat thrown over
# the jump (its rear flies 0.51 s, the whole mat 0.19 s), to 2.2 s (after
# both landings), with records every 0.05 s and every 0.2 ms. The highest
# is located at the roots of each open contact's gap rate (an apex) and at
# the records, so:
#   - with coarse records it lies above every record's open gap (the rear's
#     lift at the records where the rear is open: 0.15275 m at 0.05 s, the
#     located 0.15307 m), the rear's;
#   - it is the same with both output steps to 1e-7 m: records alone would
#     differ by 3.2e-4 m; another output step changes CVODE's steps and so
#     the run by its integration error (seen 4.1e-9 m here in Release and
#     4.5e-9 m in Debug; to 30 s, 1.9e-8 m, the landings moving by up to
#     6e-9 s);
#   - with the dense records it lies above their largest open gap by at most
#     what 0.2 ms of sampling can miss at an apex, g dt^2/8 ~ 5e-8 m (seen
#     7.7e-9 m);
#   - the summary (--summary-json: highest, highest_arc_length) and the
#     file (/sled/vehicle/flight/highest, highest_contact,
#     highest_arc_length) agree.
# Before this (main 3fa059d) a vehicle had no highest point at all.
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
for step in 0.05 0.0002; do
  (cd "$root" && "$slidesim" --set solver%duration=2.2 --set solver%output_step=$step -o "$work/mat_$step.h5" \
    --summary-json "$work/mat_$step.json" inputs/parts/mat_jump.nml >"$work/mat_$step.out" 2>"$work/mat_$step.err"); got=$?
  check '[ $got = 0 ]' "output step $step: exit status $got: $(cat "$work/mat_$step.err")"
done
check 'grep -q "highest above the slide: rear 0.153" "$work/mat_0.05.out"' \
  "the report's highest point: $(grep -A1 highest "$work/mat_0.05.out")"
out=$("$py" - "$work" <<'PY' 2>&1
import json, sys
import h5py
import numpy as np
work = sys.argv[1]
bad = []
found = {}
for step in ("0.05", "0.0002"):
    with h5py.File(f"{work}/mat_{step}.h5", "r") as f:
        s = f["sled"]
        g = s["vehicle/flight"]
        t = s["time"][:]
        lift = s["coordinates/rear_lift/value"][:]
        rear_open = (s["vehicle/open"][:] & 1) == 1
        h, c, at = g["highest"][()], g["highest_contact"][()], g["highest_arc_length"][()]
        j = json.load(open(f"{work}/mat_{step}.json"))["values"]
        if j.get("highest") != h or j.get("highest_arc_length") != at:
            bad.append(f"{step}: summary {j.get('highest')}, {j.get('highest_arc_length')} against the file's {h}, {at}")
        if c != 1:
            bad.append(f"{step}: the highest contact {c}, not 1 (the rear)")
        top = np.max(lift[rear_open])
        t_top = t[rear_open][np.argmax(lift[rear_open])]
        print(f"output step {step}: highest {h:.12f} m (contact {c}, arc length {at:.6f} m); "
              f"the records' largest open rear lift {top:.12f} m at {t_top:.6f} s")
        if not h >= top:
            bad.append(f"{step}: the highest {h} lies below a record's open gap {top}")
        found[step] = (h, top)
h_coarse, top_coarse = found["0.05"]
h_fine, top_fine = found["0.0002"]
if not abs(h_coarse - h_fine) <= 1e-7:
    bad.append(f"the highest differs with the output step: {h_coarse} and {h_fine}")
if not h_coarse - top_coarse > 1e-4:
    bad.append(f"the coarse records' largest gap {top_coarse} is as high as the located {h_coarse}: nothing located")
if not h_fine - top_fine <= 5e-8:
    bad.append(f"the highest {h_fine} lies {h_fine - top_fine} m above the dense records' largest gap {top_fine}")
if bad:
    print("; ".join(bad))
    sys.exit(1)
PY
); pyrc=$?
check '[ $pyrc = 0 ]' "the highest point: $out"
echo "$out"
echo "vehicle_highest: $checks checks, $failures failed"
[ "$failures" = 0 ]
