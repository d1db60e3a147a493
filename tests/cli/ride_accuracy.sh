#!/usr/bin/env bash
# &solver accuracy (issue 29, point 2): a preset of both integrators'
# tolerances named by what it guarantees. On the default ride (its four
# tolerances unset): accuracy = 'report' gives the same report, to the bit,
# as rtol 1e-8 / atol 1e-7 given to &solver and &water_solver, and every
# value of its report lies within 1e-4 relative of the ride at rtol 1e-12
# (the preset's guarantee; bench/accuracy_study.py measures it on every
# shipped ride); 'reference' is the shipped tolerances (the shipped run to
# the bit). Refused before any work (exit 1, the group, the variable and
# the value named): a preset with a tolerance still given in &solver or in
# &water_solver, a word that is no preset, a preset in a scenario other
# than the ride and the sweep. A sweep rides at 'report' when its input
# gives no tolerance, at the tolerances given otherwise.
set -u
slidesim=$1
repo=$(pwd)   # tests run from the repository root
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { if ! eval "$1"; then echo "FAIL $2"; failures=$((failures + 1)); fi; }
default=$repo/inputs/default.nml
unset_tolerances=(--unset solver%rtol --unset solver%atol --unset water_solver%rtol --unset water_solver%atol)

ride() {   # name, arguments...
  local name=$1; shift
  "$slidesim" -q -o "$work/$name.h5" --summary-json "$work/$name.json" "$@" "$default" \
    >"$work/$name.out" 2>"$work/$name.err"
}

ride report "${unset_tolerances[@]}" --set solver%accuracy=report; got=$?
check '[ $got = 0 ]' "accuracy = 'report': exit status $got ($(cat "$work/report.err"))"
ride explicit "${unset_tolerances[@]}" --set solver%rtol=1e-8 --set solver%atol=1e-7 \
  --set water_solver%rtol=1e-8 --set water_solver%atol=1e-7; got=$?
check '[ $got = 0 ]' "rtol 1e-8, atol 1e-7: exit status $got ($(cat "$work/explicit.err"))"
ride fine "${unset_tolerances[@]}" --set solver%rtol=1e-12 --set solver%atol=1e-11 \
  --set water_solver%rtol=1e-12 --set water_solver%atol=1e-11; got=$?
check '[ $got = 0 ]' "rtol 1e-12: exit status $got ($(cat "$work/fine.err"))"
ride shipped; got=$?
check '[ $got = 0 ]' "the shipped ride: exit status $got ($(cat "$work/shipped.err"))"
ride reference "${unset_tolerances[@]}" --set solver%accuracy=reference; got=$?
check '[ $got = 0 ]' "accuracy = 'reference': exit status $got ($(cat "$work/reference.err"))"

# same: every number of the report but the CPU times equal; within: every
# value within `bound` relative of the second's (the places of the extremes,
# in m, and the step count are not values the guarantee covers; a felt g's
# largest and smallest relative to the larger magnitude of the two, the
# quantity's scale; a value below 1e-9 in its unit is zero to rounding and
# compared absolutely: as bench/accuracy_study.py does)
"$python" - "$work" <<'EOF' || failures=$((failures + 1))
import json, sys
work = sys.argv[1]
def values(name):
    with open(f"{work}/{name}.json") as f:
        return json.load(f)["values"]
def numbers(v):
    return {k: x for k, x in v.items() if isinstance(x, (int, float)) and not isinstance(x, bool)}
failed = False
def same(a, b, why):
    global failed
    va, vb = numbers(values(a)), numbers(values(b))
    differ = [k for k in vb if not k.endswith("cpu_time") and va.get(k) != vb[k]]
    if differ:
        print(f"FAIL {why}: {a} and {b} differ in {differ[:5]}")
        failed = True
def within(a, b, bound, why):
    global failed
    va, vb = numbers(values(a)), numbers(values(b))
    worst, which = 0.0, ""
    for k, ref in vb.items():
        if k.endswith(("cpu_time", "arc_length")) or k == "ride_steps":
            continue
        scale = abs(ref)
        for pair in ("felt_longitudinal", "felt_lateral", "felt_normal"):
            if k in (pair + "_max", pair + "_min"):
                scale = max(abs(vb[pair + "_max"]), abs(vb[pair + "_min"]))
        e = abs(va[k] - ref) / max(scale, 1e-9)
        if e > worst:
            worst, which = e, k
    if not worst <= bound:
        print(f"FAIL {why}: {which} off by {worst:.2e} relative (at most {bound:g})")
        failed = True
    return worst
same("report", "explicit", "accuracy = 'report' is rtol 1e-8, atol 1e-7 for both integrators")
same("reference", "shipped", "accuracy = 'reference' is the shipped tolerances")
if numbers(values("report"))["ride_steps"] >= numbers(values("shipped"))["ride_steps"]:
    print("FAIL accuracy = 'report' takes no fewer steps than the shipped tolerances")
    failed = True
within("report", "fine", 1e-4, "accuracy = 'report' within 1e-4 of rtol 1e-12")
within("reference", "fine", 1e-6, "accuracy = 'reference' within 1e-6 of rtol 1e-12")
sys.exit(1 if failed else 0)
EOF

# ---- refusals: exit 1, nothing written, the message names where and why
refused() {   # name, expected words (a grep -E pattern), arguments (the input last)
  local name=$1 pattern=$2; shift 2
  "$slidesim" -q -o "$work/$name.h5" "$@" >"$work/$name.out" 2>"$work/$name.err"; got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1"
  check '[ ! -e "$work/$name.h5" ]' "$name: a result file was written"
  check 'grep -Eq "$pattern" "$work/$name.err"' "$name: message '$(cat "$work/$name.err")' lacks /$pattern/"
}
refused with_rtol "default.nml:14.*&solver: rtol = 1e-10 .*accuracy = 'report'" \
  --set solver%accuracy=report "$default"
refused with_water_atol "&water_solver: atol = 1e-9 .*accuracy = 'report'.*either the preset or the tolerances" \
  --unset solver%rtol --unset solver%atol --unset water_solver%rtol --set solver%accuracy=report "$default"
refused no_preset "&solver: accuracy = .?fast.? is not allowed.*reference.*report" \
  "${unset_tolerances[@]}" --set solver%accuracy=fast "$default"
refused point_mass "&solver: accuracy = .?report.? .*only the ride and the sweep" \
  --set solver%accuracy=report "$repo/inputs/parts/bowl_point_mass.nml"

# ---- the sweep: 'report' by default when the input gives no tolerance (its
# four unset: the same CSV, to the bit, as accuracy = 'report' given, and
# fewer steps than the shipped sweep); the tolerances given win over that
# default (the shipped sweep, which gives them: the same CSV as with
# accuracy = 'tolerances' given); 'report' given with them is refused
sweep_input=$repo/inputs/sweep/demo_population.nml
sweep() {   # name, arguments...
  local name=$1; shift
  "$slidesim" -q -o "$work/$name.h5" --set sweep%threads=1 "$@" "$sweep_input" >"$work/$name.out" 2>"$work/$name.err"
}
sweep sweep_default "${unset_tolerances[@]}"; got=$?
check '[ $got = 0 ]' "sweep without tolerances: exit status $got ($(cat "$work/sweep_default.err"))"
sweep sweep_report "${unset_tolerances[@]}" --set solver%accuracy=report; got=$?
check '[ $got = 0 ]' "sweep with accuracy = 'report': exit status $got ($(cat "$work/sweep_report.err"))"
sweep sweep_shipped; got=$?
check '[ $got = 0 ]' "the shipped sweep: exit status $got ($(cat "$work/sweep_shipped.err"))"
sweep sweep_tolerances --set solver%accuracy=tolerances; got=$?
check '[ $got = 0 ]' "sweep with accuracy = 'tolerances': exit status $got ($(cat "$work/sweep_tolerances.err"))"
"$python" - "$work" <<'EOF2' || failures=$((failures + 1))
import csv, sys
work = sys.argv[1]
def rows(name):
    with open(f"{work}/{name}.csv", newline="") as f:
        return [{k: v for k, v in row.items() if k != "wall_time"} for row in csv.DictReader(f)]
failed = False
for a, b, why in [("sweep_default", "sweep_report", "a sweep given no tolerance rides at 'report'"),
                  ("sweep_shipped", "sweep_tolerances", "a sweep's tolerances given win over its default")]:
    if rows(a) != rows(b):
        print(f"FAIL {why}: {a}.csv and {b}.csv differ")
        failed = True
steps = lambda name: sum(float(row["steps"]) for row in rows(name))
if not steps("sweep_default") < steps("sweep_shipped"):
    print(f"FAIL a sweep at 'report' takes no fewer steps ({steps('sweep_default')}) than the shipped "
          f"sweep ({steps('sweep_shipped')})")
    failed = True
sys.exit(1 if failed else 0)
EOF2
refused sweep_with_rtol "demo_population.nml:13.*&solver: rtol = 1e-10 .*accuracy = 'report'" \
  --set solver%accuracy=report "$sweep_input"

[ "$failures" = 0 ] && echo "ride_accuracy: all checks passed"
[ "$failures" = 0 ]
