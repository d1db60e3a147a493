#!/usr/bin/env bash
# Flights and landings in the pictures (issue 25, point 6): a ball dropped
# from 1 m (its bottom) moving sideways at 0.5 m/s on a floor, restitution
# 0.5, bounces six times and then rests (tests/cli/contact_lift_off.sh checks
# the numbers). Its results show where and when it flew and landed:
# - the XDMF file: a grid 'impacts' with one point per row of
#   /contact/impacts, at the landing points (closed form: on the floor,
#   z = 0, at x = 0.5 m/s t), with the table's time and speeds as point data;
#   'path of contact on_floor' and the moving 'contacts' carry `open` (the
#   result's /contact/contacts/on_floor/open, per record and per time step)
#   and `gap`; the file passes tests/cli/check_xdmf.py's structure checks,
#   and ParaView (pvpython) shows `open` 1 on the moving contact while the
#   ball flies and 0 once it rests; scripts/paraview_open.py colours the
#   contact by `open` and the impacts by their approach speed;
# - the plot (scripts/plot_contact.py): a PNG; its figure shades the flight
#   phases on every time plot (one span: the records with open = 1, from the
#   start to the closing impact), labels every impact with its approach speed
#   and marks the landing points in 3-D, the legend naming the bodies that
#   met ("ball on ground": /contact/impacts/body_1, body_2).
# - an impact at several contacts at once (ball_on_cart: the hit and the
#   cart's three feet) labelled once, with its fastest approach; the summary
#   counts impacts, not rows, and writes alike landings in one sentence.
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"
unset DISPLAY   # as in CI: no window, the Agg backend

cat >"$work/bounce.nml" <<'EOF'
&run scenario = 'contact', output = 'bounce.h5' /
&solver duration = 2, output_step = 0.01, rtol = 1e-10, atol = 1e-10 /
&shape name = 'floor', kind = 'plane' /
&shape name = 'ball', kind = 'sphere', radius = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball', position = 0, 0, 1.1, velocity = 0.5, 0, 0 /
&contact name = 'on_floor', shape_1 = 'floor', body_2 = 'ball', shape_2 = 'ball', start = 'open',
  restitution = 0.5, close_speed = 0.1 /
EOF
run_case bounce 0
[ -f "$work/bounce.xmf" ] || fail "bounce: no XDMF file"

# the XDMF file's structure, then its marks against the result file
"$python" "$root/tests/cli/check_xdmf.py" "$work/bounce.xmf" >"$work/structure.out" 2>&1 ||
  fail "bounce.xmf structure: $(grep FAIL "$work/structure.out" | head -5)"
"$python" - "$work/bounce.h5" "$work/bounce.xmf" <<'EOF' || fail "bounce.xmf: the flight and impact marks"
import sys
import xml.etree.ElementTree as ET
import h5py
import numpy as np

failures = []
def check(ok, what):
    if not ok:
        failures.append(what)

def numbers(element):
    """Inline numbers, or the dataset of the result a reference names."""
    item = element.find('DataItem')
    if item.get('Format') == 'HDF':
        name, _, dataset = item.text.strip().partition(':')
        check(name == 'bounce.h5', f"a reference to {name}, not bounce.h5")
        return np.asarray(f[dataset][()], dtype=float).ravel()
    return np.array(item.text.split(), dtype=float)

def attributes(grid):
    return {a.get('Name'): numbers(a) for a in grid.findall('Attribute')}

f = h5py.File(sys.argv[1], 'r')
table = f['contact/impacts']
k = len(table['time'])
time = f['contact/time'][:]
is_open = f['contact/contacts/on_floor/open'][:]
steps = ET.parse(sys.argv[2]).getroot().find('Domain').find('Grid').findall('Grid')
first = {g.get('Name'): g for g in steps[0].findall('Grid')}

impacts = first.get('impacts')
check(impacts is not None, "no grid 'impacts'")
if impacts is not None:
    xyz = numbers(impacts.find('Geometry')).reshape(-1, 3)
    check(len(xyz) == k == 6, f"'impacts' has {len(xyz)} points, the table {k} rows (6 bounces)")
    if len(xyz) == k:
        # nine significant digits in the file; the landing point on the floor
        # below the ball, which keeps its 0.5 m/s sideways (frictionless)
        check(np.allclose(xyz, table['position'][:], rtol=1e-8, atol=1e-12), "points are not /contact/impacts/position")
        check(np.allclose(xyz[:, 0], 0.5 * table['time'][:], rtol=1e-8) and np.abs(xyz[:, 1:]).max() < 1e-12,
              f"points are not the landing points (0.5 t, 0, 0): {xyz}")
        a = attributes(impacts)
        for name in ('time', 'normal_speed_before', 'normal_speed_after', 'normal_impulse', 'energy_lost', 'contact',
                     'body_1', 'body_2'):
            check(name in a and np.allclose(a[name], table[name][:], rtol=1e-8, atol=1e-12),
                  f"'impacts' point data {name} is not the table's")

path = first.get('path of contact on_floor')
check(path is not None, "no grid 'path of contact on_floor'")
if path is not None:
    a = attributes(path)
    check('open' in a and np.array_equal(a['open'], is_open), "the path's 'open' is not the result's")
    check('gap' in a and np.allclose(a['gap'], f['contact/measurements/on_floor.gap'][:], atol=1e-12),
          "the path's 'gap' is not the result's")

# the moving contact's state at each time step: that of its record (at the
# closing two records share the time: the flight's last and the rest's first)
flying = resting = 0
for step in steps:
    t = float(step.find('Time').get('Value'))
    contacts = [g for g in step.findall('Grid') if g.get('Name') == 'contacts']
    a = attributes(contacts[0]) if contacts else {}
    rows = np.flatnonzero(np.abs(time - t) <= 1e-8 * max(1.0, abs(t)))
    if 'open' not in a or len(rows) == 0 or a['open'][0] not in is_open[rows]:
        failures.append(f"step at t = {t}: the moving contact's 'open' {a.get('open')} is not its record's")
        break
    flying += a['open'][0] == 1
    resting += a['open'][0] == 0
check(flying > 0 and resting > 0, f"{flying} steps in flight, {resting} at rest")
for line in failures:
    print('FAIL', line)
print(f"bounce.xmf: {k} impacts, {len(steps)} steps ({flying} in flight), {len(failures)} failures")
sys.exit(1 if failures else 0)
EOF

# ParaView colours by `open`: in flight 1, at rest 0 (the moving contact)
if command -v pvpython >/dev/null; then
  (cd "$work" && timeout 300 pvpython - <<'EOF') >"$work/paraview.out" 2>&1 || fail "ParaView: $(tail -3 "$work/paraview.out")"
from paraview.simple import OpenDataFile
from paraview import servermanager
reader = OpenDataFile('./bounce.xmf')   # a folder in the name (docs/outputs.md)
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
for t, want in ((0.3, 1), (1.8, 0)):   # falling the first metre; resting
    step = min(times, key=lambda s: abs(s - t))
    reader.UpdatePipeline(step)
    data = servermanager.Fetch(reader)
    # the moving contact: the one-point block with `open` (the path has 208)
    found = []
    leaves = data.NewIterator()
    leaves.InitTraversal()
    while not leaves.IsDoneWithTraversal():
        block = leaves.GetCurrentDataObject()
        values = block.GetPointData().GetArray('open')
        if values is not None and block.GetNumberOfPoints() == 1:
            found.append(values.GetValue(0))
        leaves.GoToNextItem()
    print(f"t = {step}: contacts open = {found}")
    assert found == [want], (step, found, want)
print('ParaView shows the phases')
EOF
  grep 'ParaView shows' "$work/paraview.out"
  # the macro that opens a result ready to play colours the phases and impacts
  (cd "$work" && timeout 300 pvpython "$root/scripts/paraview_open.py" --no-render bounce.xmf) >"$work/macro.out" 2>&1
  for line in 'impacts: 6 points, coloured by normal_speed_before' 'contacts: 1 points, coloured by open' \
              'path of contact on_floor: [0-9]+ points, coloured by open'; do
    grep -qxE "$line" "$work/macro.out" || fail "scripts/paraview_open.py: no '$line' in: $(tail -8 "$work/macro.out")"
  done
else
  fail "pvpython not found (install paraview python3-paraview)"
fi

# 1.5 s: few enough records (158) that every one is a time step, the two
# at the closing (before and after the switch) too: they make one step (the
# readers want increasing times; the old file repeated the time)
sed -e "s|output = 'bounce.h5'|output = 'short.h5'|" -e 's|duration = 2,|duration = 1.5,|' "$work/bounce.nml" >"$work/short.nml"
run_case short 0
"$python" "$root/tests/cli/check_xdmf.py" "$work/short.xmf" >"$work/short_structure.out" 2>&1 ||
  fail "short.xmf structure: $(grep FAIL "$work/short_structure.out" | head -5)"
grep -c '<Time Value=' "$work/short.xmf" | grep -qx 157 || fail "short.xmf: $(grep -c '<Time Value=' "$work/short.xmf") steps, not 157 (158 records, two at the closing)"

# the plot: a PNG, and in its figure the phases and the impacts
(cd "$work" && "$python" "$root/scripts/plot_contact.py" bounce.h5 -o bounce.png) >"$work/plot.out" 2>&1 ||
  fail "plot_contact.py: $(cat "$work/plot.out")"
cmp -s <(head -c 8 "$work/bounce.png") <(printf '\211PNG\r\n\032\n') || fail "plot_contact.py wrote no PNG"
"$python" - "$root/python" "$work/bounce.h5" <<'EOF' || fail "plot_contact.py: the flight and impact marks"
import sys
sys.path.insert(0, sys.argv[1])
import h5py
import matplotlib
matplotlib.use('Agg')
import numpy as np
from slidesim.plot import figure

with h5py.File(sys.argv[2], 'r') as f:
    t_impacts = f['contact/impacts/time'][:]
    speeds = -f['contact/impacts/normal_speed_before'][:]
    landings = f['contact/impacts/position'][:]
    t0 = f['contact/time'][0]
fig = figure(sys.argv[2])
failures = []
time_axes = [ax for ax in fig.axes if ax.get_xlabel() == 'time [s]']
for ax in time_axes:
    spans = [p for p in ax.patches if p.get_gid() == 'flight']
    if len(spans) != 1:
        failures.append(f"'{ax.get_title()}': {len(spans)} flight spans, not 1")
        continue
    x = spans[0].get_xy()[:, 0]
    if abs(x.min() - t0) > 1e-12 or abs(x.max() - t_impacts[-1]) > 1e-12:
        failures.append(f"'{ax.get_title()}': flight from {x.min()} to {x.max()}, not {t0} to {t_impacts[-1]}")
labels = [a for ax in fig.axes for a in ax.texts if a.get_gid() == 'impact']
if [a.get_text() for a in labels] != [f"{v:.3g} m/s" for v in speeds] or len(labels) != 6:
    failures.append(f"impact labels {[a.get_text() for a in labels]}, speeds {speeds}")
elif not np.allclose([a.xy[0] for a in labels], t_impacts):
    failures.append("impact labels not at the impacts' times")
marks = [c for ax in fig.axes for c in ax.collections if c.get_gid() == 'impact_position']
if len(marks) != 1 or not np.allclose(np.column_stack(marks[0]._offsets3d), landings):
    failures.append("the landing points are not marked in 3-D")
elif marks[0].get_label() != 'impacts (6): ball on ground':
    failures.append(f"the landing points' legend {marks[0].get_label()!r} does not name the bodies")
if len(time_axes) != 4:
    failures.append(f"{len(time_axes)} time plots, expected 4 (angular velocity, gap, forces, energy)")
for line in failures:
    print('FAIL', line)
print(f"plot: {len(time_axes)} time plots shaded, {len(labels)} impacts labelled, {len(failures)} failures")
sys.exit(1 if failures else 0)
EOF


# An impact at several contacts at once is one label, its fastest approach:
# the ball landing on the cart (inputs/contact/ball_on_cart.nml) is one row
# for the hit and one for each of the cart's three feet (0 m/s); seven
# landings, seven labels (each was four, written over each other).
sed -e "s|output = 'ball_on_cart.h5'|output = 'cart.h5'|" "$root/inputs/contact/ball_on_cart.nml" >"$work/cart.nml"
run_case cart 0
# The summary counts those seven impacts (not the table's 28 rows) and says
# the six alike landings before the last (the cart's feet closed, the ball
# open) in one sentence, not six: the outcome stays short however often the
# ball lands (it was 1848 characters).
(cd "$work" && "$slidesim" cart.nml -o cart_summary.h5 >cart_summary.out 2>&1) || fail "cart: summary run"
grep -qE '^  impacts +7 \(landings; 28 rows of /contact/impacts\)$' "$work/cart_summary.out" ||
  fail "cart: summary's impacts: $(grep '  impacts ' "$work/cart_summary.out")"
stopped=$(grep '^  stopped at ' "$work/cart_summary.out")
# (times as the event finder places them, to 4 digits: the builds differ in the last)
echo "$stopped" | grep -qE "lands on 'ball_on_cart' at t = 0\.2473[0-9]* \.\. 0\.9317[0-9]* s \(6 times\) while 'rear_left_on_floor', .*'ball_on_cart' open; body 'ball' lands on 'ball_on_cart' at t = 0\.9547[0-9]* s while .*'ball_on_cart' closed; the end of the simulated time$" ||
  fail "cart: the landings' outcome: $stopped"
[ "${#stopped}" -lt 700 ] || fail "cart: the outcome is ${#stopped} characters"
(cd "$work" && "$python" "$root/scripts/plot_contact.py" cart.h5 -o cart.png) >"$work/cart_plot.out" 2>&1 ||
  fail "plot_contact.py cart.h5: $(cat "$work/cart_plot.out")"
"$python" - "$root/python" "$work/cart.h5" <<'EOF' || fail "plot_contact.py: one label per impact event"
import sys
sys.path.insert(0, sys.argv[1])
import h5py
import matplotlib
matplotlib.use('Agg')
import numpy as np
from slidesim.plot import figure

with h5py.File(sys.argv[2], 'r') as f:
    times = f['contact/impacts/time'][:]
    speeds = -f['contact/impacts/normal_speed_before'][:]
fig = figure(sys.argv[2])
labels = [a for ax in fig.axes for a in ax.texts if a.get_gid() == 'impact']
events = np.unique(times)
expected = [f"{speeds[times == t].max():.3g} m/s" for t in events]
got = [a.get_text() for a in labels]
ok = len(times) > len(events) == 7 and got == expected and np.allclose([a.xy[0] for a in labels], events)
print(f"cart: {len(times)} impact rows at {len(events)} times, labels {got}")
sys.exit(0 if ok else 1)
EOF

finish
