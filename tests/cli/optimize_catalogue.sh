#!/usr/bin/env bash
# Designs from standard parts (docs/design.md): scenario optimize over
# element parameters, the optimum snapped to a catalogue.
# - the shipped input runs (exit 0, file complete): every design variable of
#   the design chosen is one of its allowed values, inside its bounds; the
#   design chosen is the feasible one of least acceleration cost among the
#   designs ridden, and its rides' cost is the one reported; the parts list
#   counts the six elements, the entry and the fifth straight alike as one
#   part of two;
#   the summary and its JSON list the parts;
# - every &catalogue and &design_elements input is used or refused (exit 1,
#   nothing written), the message naming the group, variable, value and
#   what is allowed: a catalogue without an element design, an empty one, a
#   value outside every bound, one for a parameter no variable has, a
#   variable without values, a list not increasing, a list and a step, a
#   step with no value inside the bounds; a parameter its element lacks,
#   bounds that miss the start value or leave the range its element allows, an
#   element that is not there, a variable given twice, a point variable of
#   &optimize with an element design, too few rides, no chain to vary.
set -u
slidesim=$1
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
. "$(dirname "$0")/support/checks.sh"
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
input=$root/inputs/design/optimize_standard_parts.nml

(cd "$work" && "$slidesim" -q --summary-json parts.json -o parts.h5 "$input" >parts.out 2>parts.err)
rc=$?
if [ "$rc" != 0 ]; then
  fail "shipped input: exit status $rc: $(cat "$work/parts.err")"
else
  grep -q '2 x straight, length 3 m, slope 8 deg (elements 1, 5)' "$work/parts.out" || \
    fail "summary: no parts list with the two straights: $(cat "$work/parts.out")"
  "$python" - "$work/parts.h5" "$work/parts.json" <<'PY' || fail "shipped input: the file or the JSON (above)"
import json
import sys
import h5py
import numpy as np
bad = []
with h5py.File(sys.argv[1], "r") as f:
    g = f["/optimize"]
    if f.attrs["status"] != "complete":
        bad.append(f"status {f.attrs['status']}")
    k = 1
    while f"variables/variable_{k}" in g:
        v = g[f"variables/variable_{k}"]
        x, allowed = float(v["catalogue"][()]), v["allowed"][:]
        if not np.any(allowed == x) or not float(v["lower"][()]) <= x <= float(v["upper"][()]):
            bad.append(f"variable {k}: {x} not an allowed value {allowed} inside its bounds")
        if not np.any(g[f"catalogue/variable_{k}"][:] == x):
            bad.append(f"variable {k}: {x} not among the designs ridden")
        k += 1
    if k != 4:
        bad.append(f"{k - 1} design variables, expected 3")
    cost, feasible = g["catalogue/acceleration_cost"][:], g["catalogue/feasible"][:] == 1
    chosen = float(g["chosen/acceleration_cost"][()])
    if not feasible.any() or chosen != cost[feasible].min():
        bad.append(f"chosen cost {chosen}, the least feasible of the designs ridden is {cost[feasible].min()}")
    if g["parts/count"][:].sum() != 6 or sorted(g["parts/count"][:]) != [1, 1, 1, 1, 2]:
        bad.append(f"parts counted {g['parts/count'][:]}, expected 2 x the straight and 1 x four others")
    if not np.all(np.isin(g["parts/radius"][:][g["parts/kind"][:] == 2], g["variables/variable_1/allowed"][:])):
        bad.append(f"a curve's radius is not in the catalogue: {g['parts/radius'][:]}")
    # the kinds' numbers name every kind of a slide chain (on 3e73489 the
    # text stopped at "5 drop": no bowl, funnel or patch)
    legend = g["parts/kind"].attrs["description"]
    legend = legend.decode() if isinstance(legend, bytes) else legend
    if "1 straight, 2 curve, 3 helix, 4 runout, 5 drop, 6 bowl, 7 funnel, 8 patch" not in legend:
        bad.append(f"parts/kind's description lacks a kind: {legend}")
    values = json.load(open(sys.argv[2]))["values"]
    if values.get("elements") != 6 or values.get("catalogue_acceleration_cost") != chosen:
        bad.append(f"JSON: elements {values.get('elements')}, catalogue cost {values.get('catalogue_acceleration_cost')}")
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
fi

check_refused outside 'radii(3) = 12.0 is not allowed: lies outside the bounds of every radius variable' \
  --set 'catalogue%radii=3,4,12' "$input"
check_refused not_a_variable "no design variable of &design_elements has parameter = 'angle'" \
  --set 'catalogue%angle_step_deg=15' "$input"
check_refused no_values 'design variable 3 (element 3 slope) needs its allowed values: give slopes_deg or slope_step_deg' \
  --unset catalogue%slope_step_deg "$input"
check_refused not_increasing 'radii(3) = 4.0 is not allowed: must exceed radii(2) = 5.0' --set 'catalogue%radii=3,5,4' "$input"
check_refused list_and_step 'give radii or radius_step, not both' --set 'catalogue%radius_step=1' "$input"
check_refused no_value_inside 'holds no value inside the bounds 4 … 12 deg of design variable 3' \
  --set 'catalogue%slope_step_deg=13' "$input"
# the list's range is the one &slide_elements takes for these slopes (was
# [-60, 60] while no element could be built beyond 45 deg)
check_refused steep_list 'slopes_deg(2) = 50 is not allowed: must be a finite number in [-45, 45] (deg)' --unset catalogue%slope_step_deg \
  --set 'catalogue%slopes_deg=4,50' "$input"
check_refused steep_step 'slope_step_deg = 50 is not allowed: must be a finite number > 0 and <= 45 (deg)' --set 'catalogue%slope_step_deg=50' "$input"
check_refused empty '&catalogue is empty' --unset catalogue%radii --unset catalogue%slope_step_deg "$input"
check_refused wrong_parameter 'element 1 is a straight, whose radius is not a design variable (a radius: curve, helix, bowl, funnel, drop)' \
  --set 'design_elements%element=1,4,3' "$input"
check_refused start_outside 'must hold the start value 4 m of element 2' --set 'design_elements%lower=4.5,3,4' "$input"
check_refused out_of_range "upper(3) = 70.0 is not allowed: element 3 is a straight, and a straight's slope must lie in [-45, 45]" \
  --set 'design_elements%upper=8,8,70' "$input"
check_refused no_element 'must be the number of an element of &slide_elements, 1 to n_elements = 6' \
  --set 'design_elements%element=2,9,3' "$input"
check_refused twice 'the radius of element 2 is already design variable 1' --set 'design_elements%element=2,2,3' "$input"
check_refused points 'n_points = 9 is not allowed: the design is the element chain of &slide_elements' \
  --set 'optimize%n_points=9' "$input"
check_refused few_rides 'give at least 2 rides for 3 design variables' --set 'optimize%start_angles_deg=0' "$input"
# a catalogue without an element design (and its elements)
sed '/^&design_elements/,/^\//d; /^&slide_elements/,/^\//d' "$input" >"$work/no_design.nml"
check_refused no_design '&catalogue is not used: an optimisation of element parameters needs &design_elements' \
  "$work/no_design.nml"
sed '/^&slide_elements/,/^\//d' "$input" >"$work/no_chain.nml"
check_refused no_chain '&design_elements varies the elements of &slide_elements, which is missing' "$work/no_chain.nml"
[ "$failures" = 0 ]
