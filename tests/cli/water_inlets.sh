#!/usr/bin/env bash
# Several inlets (&inlet, docs/water.md "Several inlets"):
# - bad inlets stop before any work: exit status 1, a message naming the
#   file and line, &inlet, the variable, its value and what is allowed, and
#   no result file (beyond the slide's end, upstream of the start, negative
#   flow, a direction beyond +-1.5 rad, a missing place, out of order);
# - the shipped example inputs/water/two_inlets.nml runs (exit 0) and writes
#   the flow rate along the slide (units, description) and the inlets, the
#   flow jumping from 3 to 5 l/s at 25 m; a one-inlet run writes neither
#   (its layout as before);
# - a ride takes &inlet too: its water has the inlet.
# One check per case; checks = passed + failed.
set -u
slidesim=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0; checks=0

expect() {
  local name=$1 want=$2; shift 2
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$name.nml" >"$name.out" 2>"$name.err")
  local got=$?
  local ok=1
  [ "$got" = "$want" ] || { echo "FAIL $name: exit status $got, expected $want"; ok=0; }
  for needle in "$@"; do
    grep -qF -- "$needle" "$work/$name.err" || { echo "FAIL $name: message lacks '$needle'"; ok=0; }
  done
  if ls "$work"/*.h5 "$work"/*.h5.tmp >/dev/null 2>&1; then
    echo "FAIL $name: a result file was left behind"; ok=0; rm -f "$work"/*.h5 "$work"/*.h5.tmp
  fi
  if [ $ok = 0 ]; then failures=$((failures + 1)); echo "  message: $(cat "$work/$name.err")"; fi
}

head="&run scenario = 'water', output = 'w.h5' /
&channel kind = 'straight', incline_deg = 10, length = 20 /
&water start = 'speed', speed0 = 2, u0 = 2 /"
mk() { printf "%s\n%s\n" "$head" "$2" > "$work/$1.nml"; }

mk beyond_end "&inlet arc_length = 20, flow_rate = 0.001 /"
expect beyond_end 1 'beyond_end.nml:4' '&inlet' 'arc_length = 20' 'before its end (20' 'from the &water start (2'
mk upstream "&inlet arc_length = 1, flow_rate = 0.001 /"
expect upstream 1 'upstream.nml:4' '&inlet' 'arc_length = 1' 'from the &water start (2'
mk negative_flow "&inlet arc_length = 5, flow_rate = -0.001 /"
expect negative_flow 1 'negative_flow.nml:4' '&inlet' 'flow_rate = -0.001' 'in [1.0E-06, 1] (m^3/s)'
mk direction "&inlet arc_length = 5, flow_rate = 0.001, beta = 1.6 /"
expect direction 1 'direction.nml:4' '&inlet' 'beta = 1.6' 'in [-1.5, 1.5] (rad)'
mk no_place "&inlet flow_rate = 0.001 /"
expect no_place 1 'no_place.nml:4' '&inlet' 'arc_length' 'needs its place'
mk no_flow "&inlet arc_length = 5 /"
expect no_flow 1 'no_flow.nml:4' '&inlet' 'flow_rate' 'needs its flow rate'
mk out_of_order "&inlet arc_length = 8, flow_rate = 0.001 /
&inlet arc_length = 5, flow_rate = 0.001 /"
expect out_of_order 1 'out_of_order.nml:5' '&inlet' 'arc_length = 5' 'at or after the previous one' 
mk second_beyond "&inlet arc_length = 8, flow_rate = 0.001 /
&inlet arc_length = 25, flow_rate = 0.001 /"
expect second_beyond 1 'second_beyond.nml:5' '&inlet' 'arc_length = 25'

# the shipped example, and a run without &inlet
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q -o two.h5 "$root/inputs/water/two_inlets.nml" >two.out 2>two.err)
rc=$?
printf "%s\n" "$head" > "$work/one.nml"
(cd "$work" && "$slidesim" -q -o one.h5 one.nml >one.out 2>one.err)
rc_one=$?
if [ "$rc" != 0 ] || [ "$rc_one" != 0 ]; then
  echo "FAIL example: exit status $rc (two inlets), $rc_one (one)"; cat "$work/two.err" "$work/one.err"
  failures=$((failures + 1))
else
  "$python" - "$work/two.h5" "$work/one.h5" <<'PY' || failures=$((failures + 1))
import sys
import h5py
import numpy as np
two, one = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
bad = []
q = two["/water/flow_rate"]
if q.attrs["units"] != "m^3/s" or not q.attrs["description"]:
    bad.append(f"flow_rate attributes {dict(q.attrs)}")
q = q[()]
jumps = np.nonzero(np.diff(q))[0]
s = two["/water/arc_length"][()]
if len(jumps) != 1 or q[0] != 0.003 or abs(q[-1] - 0.005) > 1e-15 or abs(s[jumps[0]] - 25) > 1e-9:
    bad.append(f"flow rate: jumps at {s[jumps]}, from {q[0]} to {q[-1]}")
if two["/water/inlets/joined"][()].tolist() != [1] or two["/water/inlets/arc_length"][()].tolist() != [25.0]:
    bad.append("the inlet not recorded as joined at 25 m")
table = two["/water/table/flow_rate"][()]
if table[0] != 0.003 or abs(table[-1] - 0.005) > 1e-15:
    bad.append(f"table flow rate {table[0]} ... {table[-1]}")
for name in ("/water/flow_rate", "/water/inlets", "/water/table/flow_rate"):
    if name in one:
        bad.append(f"one inlet: {name} written")
for b in bad:
    print("FAIL example:", b)
sys.exit(1 if bad else 0)
PY
fi

# a ride with an inlet: its water takes it
checks=$((checks + 1))
cat > "$work/ride.nml" <<'EOF2'
&run scenario = 'ride', output = 'ride.h5' /
&surface kind = 'slide' /
&slide_elements n_elements = 1, start = 0.0, 0.0, 10.0, kind = 'straight', length = 15.0, slope_deg = 12.0 /
&cross_section radius = 0.5 /
&water start = 'speed', speed0 = 2, flow_rate = 0.003 /
&inlet arc_length = 6, flow_rate = 0.002, speed = 1 /
&rider u0 = 1.0 /
EOF2
(cd "$work" && "$slidesim" -q ride.nml >ride.out 2>ride.err)
rc=$?
if [ "$rc" != 0 ] && [ "$rc" != 4 ]; then
  echo "FAIL ride: exit status $rc"; cat "$work/ride.err"; failures=$((failures + 1))
else
  "$python" - "$work/ride.h5" <<'PY' || failures=$((failures + 1))
import sys
import h5py
f = h5py.File(sys.argv[1], "r")
if f["/water/inlets/joined"][()].tolist() != [1] or abs(f["/water/flow_rate"][-1] - 0.005) > 1e-15:
    print("FAIL ride: its water lacks the inlet")
    sys.exit(1)
PY
fi

echo "water_inlets: $checks checks, $failures failed"
[ "$failures" = 0 ]
