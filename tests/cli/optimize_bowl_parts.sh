#!/usr/bin/env bash
# A bowl's size as design variables of a design from standard parts
# (docs/design.md, "Designs from standard parts"):
# - the shipped input inputs/design/optimize_bowl_parts.nml runs (exit 0,
#   file complete): every design variable of the design chosen (the bowl's
#   entry radius, wall slope, drop) is one of its allowed values inside its
#   bounds, the design chosen is the feasible one of least acceleration cost
#   among the designs ridden, and the parts list holds one bowl of exactly
#   those values (file and summary);
# - every new &catalogue kind and &design_elements value is used or refused
#   (exit 1, nothing written), the message naming the group, the variable,
#   the value and what is allowed: a bowl list value outside every bound, a
#   list for a kind no variable has (the curves' radii with only a bowl's),
#   a bowl variable without values, a list and a step, a step with no value
#   inside the bounds, a list value outside the declared range, bounds
#   outside the range of a bowl's wall slope (&slide_elements' own limit), a drop on a straight and a drop's drop
#   (not design variables), a bowl's turns (not a parameter).
set -u
slidesim=$1
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
. "$(dirname "$0")/support/checks.sh"
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
input=$root/inputs/design/optimize_bowl_parts.nml

(cd "$work" && "$slidesim" -q -o bowl.h5 "$input" >bowl.out 2>bowl.err)
rc=$?
if [ "$rc" != 0 ]; then
  fail "shipped input: exit status $rc: $(cat "$work/bowl.err")"
else
  grep -q '^ *1 x bowl left, sphere, entry radius .* m from its axis, wall slope .* deg, drop .* m, turns 1 (element 2)' \
    "$work/bowl.out" || fail "summary: no parts list with the bowl: $(cat "$work/bowl.out")"
  "$python" - "$work/bowl.h5" <<'PY' || fail "shipped input: the file (above)"
import sys
import h5py
import numpy as np
bad = []
with h5py.File(sys.argv[1], "r") as f:
    g = f["/optimize"]
    if f.attrs["status"] != "complete":
        bad.append(f"status {f.attrs['status']}")
    chosen = {}
    for k, name in enumerate(["radius", "slope", "drop"], start=1):
        v = g[f"variables/variable_{k}"]
        label = v["name"][()]
        label = label.decode() if isinstance(label, bytes) else str(label)
        if label != f"element 2 (bowl) {name}":
            bad.append(f"variable {k} is '{label}', expected the bowl's {name}")
        x, allowed = float(v["catalogue"][()]), v["allowed"][:]
        if not np.any(allowed == x) or not float(v["lower"][()]) <= x <= float(v["upper"][()]):
            bad.append(f"variable {k}: {x} not an allowed value {allowed} inside its bounds")
        chosen[name] = x
    if "variables/variable_4" in g:
        bad.append("more than 3 design variables")
    cost, feasible = g["catalogue/acceleration_cost"][:], g["catalogue/feasible"][:] == 1
    ridden = float(g["chosen/acceleration_cost"][()])
    if not feasible.any() or ridden != cost[feasible].min():
        bad.append(f"chosen cost {ridden}, the least feasible of the designs ridden is {cost[feasible].min()}")
    kinds, counts = g["parts/kind"][:], g["parts/count"][:]
    bowls = np.flatnonzero(kinds == 6)
    if len(bowls) != 1 or counts[bowls[0]] != 1:
        bad.append(f"parts: kinds {kinds}, counts {counts}: expected one bowl")
    else:
        b = bowls[0]
        part = (float(g["parts/radius"][b]), float(g["parts/slope"][b]), float(g["parts/drop"][b]))
        if part != (chosen["radius"], chosen["slope"], chosen["drop"]):
            bad.append(f"the bowl part {part} is not the design chosen {chosen}")
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
fi

check_refused outside '&catalogue: bowl_radii(3) = 12.0 is not allowed: lies outside the bounds of every bowl radius variable (element 2 radius 5 … 8 m)' \
  --set 'catalogue%bowl_radii=5,6,12' "$input"
check_refused curve_radii "radii = 3, 4 is not allowed: no design variable of &design_elements has parameter = 'radius' on a curve or helix" \
  --set 'catalogue%radii=3,4' "$input"
check_refused no_values 'bowl_drops = none is not allowed: design variable 3 (element 2 drop) needs its allowed values: give bowl_drops or bowl_drop_step' \
  --unset catalogue%bowl_drops "$input"
check_refused list_and_step 'give bowl_radii or bowl_radius_step, not both' --set 'catalogue%bowl_radius_step=1' "$input"
check_refused no_value_inside 'holds no value inside the bounds 40 … 55 deg of design variable 2 (element 2 slope)' \
  --set 'catalogue%bowl_slope_step_deg=60' "$input"
check_refused declared_range 'bowl_slopes_deg' --unset catalogue%bowl_slope_step_deg --set 'catalogue%bowl_slopes_deg=45,90' \
  "$input"
check_refused slope_range "upper(2) = 88.0 is not allowed: element 2 is a bowl, and a bowl's wall rises at its entry at a slope in (0, 85] (deg) (&slide_elements)" \
  --set 'design_elements%upper=8,88,2.5' "$input"
check_refused straight_drop "element 1 is a straight, whose drop is not a design variable (a drop: bowl)" \
  --set 'design_elements%element=2,2,1' "$input"
check_refused drop_drop "element 1 is a drop, whose drop is not a design variable (a drop: bowl)" \
  --set "slide_elements%kind='drop','bowl','straight','runout'" --set 'slide_elements%length=0,0,10,8' \
  --set 'slide_elements%slope_deg=80,50,14,2' --set 'slide_elements%radius=8,6,0,0' \
  --set 'slide_elements%drop=10,2,0,0' --set 'design_elements%element=2,2,1' "$input"
check_refused turns "parameter(3) = 'turns' is not allowed" --set "design_elements%parameter='radius','slope','turns'" "$input"
[ "$failures" = 0 ]
