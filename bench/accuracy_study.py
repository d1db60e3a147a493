#!/usr/bin/env python3
"""How the ride report's numbers converge with the integrator's tolerances.

Usage: bench/accuracy_study.py BUILD [--quick] [--presets] [--sweep] [--plain]

For every shipped ride (inputs/default.nml, inputs/ride/demo_slide.nml,
inputs/parts/drop.nml, inputs/parts/halfpipe.nml, inputs/parts/bowl.nml) and the two riders of the
shipped sweep (inputs/sweep/demo_population.nml) on the default slide, the
ride is run with both integrators (the rider's &solver and the water's &water_solver) at
rtol = 1e-4 ... 1e-11 (atol = 10 rtol, as the shipped 1e-10 / 1e-9) and
compared with a reference at rtol = 1e-12. Each number of the JSON summary
(`--summary-json`) is compared:
  - values in the summary's own unit: relative error |x - ref| / |ref|
    (forces, speeds, felt g, angles, distances, times); a felt g's largest
    and smallest of one direction relative to the larger magnitude of the
    two (the quantity's scale: an extreme near zero carries the error of the
    whole quantity; --plain: relative to itself alone), a value below 1e-9
    in its unit relative to 1e-9 (zero to rounding);
  - the arc lengths where an extreme happens: absolute error in m (an extreme
    with two near-equal peaks may move between them; that is reported, not
    hidden).
A second part runs each accuracy preset (&solver accuracy, both integrators'
tolerances; src/design/design_ride_accuracy.f90) against the same reference
and checks the bound it promises (PRESETS below, the same numbers): the
script exits 1 if a ride exceeds it. A third part keeps rtol = 1e-12 and
varies the output step (0.01 s shipped):
the report's maxima and minima are located between the records on the
integrator's dense output, so the output step should not limit them (before
they were taken over the records and were good only to the record spacing).
A last part (--sweep: only it) runs the shipped sweep
(inputs/sweep/demo_population.nml, its four rides) itself at each preset and
at rtol 1e-12 and compares every number of its CSV summary ride by ride (the
report figures and the limits' worst and excess, as above; the limits'
verdicts must agree): what a sweep reports, not a ride standing in for it.

The tables it prints are the ones in docs/accuracy.md (made with a Release
build; re-run it to check them).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTOLS = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11]
REFERENCE_RTOL = 1e-12
OUTPUT_STEPS = [0.01, 0.005, 0.002, 0.001]
SKIP = {"ride_cpu_time", "water_cpu_time", "ride_steps"}
# the presets of src/design/design_ride_accuracy.f90: name, rtol, atol, and
# the relative error every report value must stay within against rtol 1e-12
PRESETS = [("reference", 1e-10, 1e-9, 1e-6), ("report", 1e-8, 1e-7, 1e-4)]
# a value below this in its unit is zero to rounding (the lateral felt g of a
# straight symmetric section, ~1e-17 g): its error is taken against this
ZERO = 1e-9
# the felt g's extremes come in pairs (largest, smallest of one direction)
FELT_PAIRS = ("felt_longitudinal", "felt_lateral", "felt_normal")
PLAIN = False   # --plain: every value's error relative to itself alone
SWEEP = os.path.join(ROOT, "inputs/sweep/demo_population.nml")
# columns of the sweep's CSV that are not results of the integration
SWEEP_INPUT_COLUMNS = {"ride", "status", "sex", "mass", "height", "mu", "u0", "v0", "heading0_deg", "speed0",
                       "flow_rate", "f1", "f2", "f3", "water_group", "wall_time", "message", "steps"}
UNSET_TOLERANCES = ["--unset", "solver%rtol", "--unset", "solver%atol",
                    "--unset", "water_solver%rtol", "--unset", "water_solver%atol"]


def cases():
    """(name, input, --set arguments) of the rides studied: the shipped rides,
    and the two riders of the shipped sweep (inputs/sweep/demo_population.nml,
    paired: female 50 kg 1.60 m at 4 l/s, male 100 kg 1.90 m at 6 l/s) on the
    default slide."""
    default = os.path.join(ROOT, "inputs/default.nml")
    return [
        ("default", default, []),
        ("ride/demo_slide", os.path.join(ROOT, "inputs/ride/demo_slide.nml"), []),
        ("parts/drop", os.path.join(ROOT, "inputs/parts/drop.nml"), []),
        ("parts/halfpipe", os.path.join(ROOT, "inputs/parts/halfpipe.nml"), []),
        ("parts/bowl", os.path.join(ROOT, "inputs/parts/bowl.nml"), []),
        ("female 50 kg", default, ["rider%sex=female", "rider%mass=50", "rider%height=1.6",
                                   "water%flow_rate=0.004"]),
        ("male 100 kg", default, ["rider%sex=male", "rider%mass=100", "rider%height=1.9",
                                  "water%flow_rate=0.006"]),
    ]


def run(binary, path, sets, rtol, output_step=None, preset=None):
    """The JSON summary of a ride at rtol (atol = 10 rtol, both integrators),
    or at an accuracy preset (the input's tolerances unset)."""
    with tempfile.TemporaryDirectory() as tmp:
        summary = os.path.join(tmp, "s.json")
        args = [binary, "-q", "-o", os.path.join(tmp, "r.h5"), "--summary-json", summary]
        args += tolerance_arguments(rtol, preset)
        if output_step is not None:
            args += ["--set", f"solver%output_step={output_step:g}"]
        for s in sets:
            args += ["--set", s]
        args.append(path)
        done = subprocess.run(args, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"accuracy_study: {' '.join(args)} failed ({done.returncode}):\n{done.stderr}")
        with open(summary) as f:
            return json.load(f)


def tolerance_arguments(rtol, preset):
    """--unset/--set arguments for a preset, or rtol (atol = 10 rtol) for both integrators."""
    if preset is not None:
        return UNSET_TOLERANCES + ["--set", f"solver%accuracy={preset}"]
    args = []
    for group in ("solver", "water_solver"):
        args += ["--set", f"{group}%rtol={rtol:g}", "--set", f"{group}%atol={10 * rtol:g}"]
    return args


def run_sweep(binary, rtol, preset=None):
    """The shipped sweep's CSV rows (one dict per ride) at rtol or a preset, one thread."""
    with tempfile.TemporaryDirectory() as tmp:
        args = [binary, "-q", "-o", os.path.join(tmp, "s.h5"), "--set", "sweep%threads=1"]
        args += tolerance_arguments(rtol, preset) + [SWEEP]
        done = subprocess.run(args, capture_output=True, text=True, cwd=ROOT)
        if done.returncode != 0:
            sys.exit(f"accuracy_study: {' '.join(args)} failed ({done.returncode}):\n{done.stderr}")
        with open(os.path.join(tmp, "s.csv"), newline="") as f:
            return list(csv.DictReader(f))


def sweep_errors(rows, reference):
    """errors() over the sweep's rides, and the verdicts that differ from the reference's."""
    worst = (0.0, "", 0.0, "")
    verdicts = []
    for i, (row, ref) in enumerate(zip(rows, reference), start=1):
        if row["status"] != ref["status"]:
            verdicts.append(f"ride {i} status {row['status']} (reference {ref['status']})")
        values, reference_values = {}, {}
        for name, x in ref.items():
            if name in SWEEP_INPUT_COLUMNS:
                continue
            if name.endswith("_verdict"):
                if row[name] != x:
                    verdicts.append(f"ride {i} {name} {row[name]} (reference {x})")
                continue
            values[name], reference_values[name] = float(row[name]), float(x)
        rel, rel_name, arc, arc_name = errors({"values": values}, {"values": reference_values})
        if rel > worst[0]:
            worst = (rel, f"ride {i} {rel_name}", worst[2], worst[3])
        if arc > worst[2]:
            worst = (worst[0], worst[1], arc, f"ride {i} {arc_name}")
    return worst, verdicts


def scale(name, reference):
    """What the error of a report value is relative to: the value itself, or,
    for a felt g's largest or smallest, the larger magnitude of the two (the
    quantity's scale over the ride: an extreme near zero, as the half-pipe's
    smallest lateral felt g, -1.2e-5 g beside its largest 0.013 g, carries
    the error of the whole quantity, about rtol times its scale); at least ZERO."""
    values = reference["values"]
    magnitude = abs(values[name])
    for pair in ([] if PLAIN else FELT_PAIRS):
        if name in (pair + "_max", pair + "_min"):
            magnitude = max(abs(values[pair + "_max"]), abs(values[pair + "_min"]))
    return max(magnitude, ZERO)


def errors(values, reference):
    """Largest relative error of the values and largest absolute error (m) of the arc lengths."""
    worst_rel, worst_rel_name, worst_arc, worst_arc_name = 0.0, "", 0.0, ""
    for name, ref in reference["values"].items():
        if name in SKIP or not isinstance(ref, (int, float)) or isinstance(ref, bool):
            continue
        x = values["values"][name]
        if name.endswith("arc_length"):
            e = abs(x - ref)
            if e > worst_arc:
                worst_arc, worst_arc_name = e, name
        else:
            e = abs(x - ref) / scale(name, reference)
            if e > worst_rel:
                worst_rel, worst_rel_name = e, name
    return worst_rel, worst_rel_name, worst_arc, worst_arc_name


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", help="a build folder holding slidesim")
    parser.add_argument("--quick", action="store_true", help="only the default ride")
    parser.add_argument("--presets", action="store_true", help="only the presets against the reference")
    parser.add_argument("--sweep", action="store_true", help="only the shipped sweep at the presets")
    parser.add_argument("--plain", action="store_true",
                        help="a felt g's extremes relative to themselves, not to the larger of the pair")
    args = parser.parse_args()
    global PLAIN
    PLAIN = args.plain
    binary = os.path.join(args.build, "slidesim")
    if not os.access(binary, os.X_OK):
        sys.exit(f"accuracy_study: no slidesim in {args.build}")
    exceeded = []
    if not args.sweep:
        study_rides(binary, args, exceeded)
    if args.sweep or not (args.quick or args.presets):
        study_sweep(binary, exceeded)
    if exceeded:
        sys.exit("accuracy_study: a preset misses its bound: " + "; ".join(exceeded))


def study_sweep(binary, exceeded):
    """The shipped sweep's CSV at each preset against the sweep at rtol 1e-12."""
    print("\n## The shipped sweep (inputs/sweep/demo_population.nml, 4 rides) at the presets against rtol 1e-12\n")
    print("| accuracy | rtol, atol | worst relative error (ride, which) | promised | "
          "worst arc-length error, m (ride, which) | steps (4 rides) | verdicts |")
    print("|---|---|---|---|---|---|---|")
    reference = run_sweep(binary, REFERENCE_RTOL)
    for preset, rtol, atol, bound in PRESETS:
        rows = run_sweep(binary, None, preset)
        (rel, rel_name, arc, arc_name), verdicts = sweep_errors(rows, reference)
        verdict = f"{bound:.0e}" + ("" if rel <= bound else " EXCEEDED")
        if rel > bound:
            exceeded.append(f"the sweep at {preset}: {rel:.1e} > {bound:.0e}")
        if verdicts:
            exceeded.append(f"the sweep at {preset}: " + ", ".join(verdicts))
        steps = sum(int(float(row["steps"])) for row in rows)
        print(f"| {preset} | {rtol:.0e}, {atol:.0e} | {rel:.1e} ({rel_name}) | {verdict} | "
              f"{arc:.1e} ({arc_name}) | {steps} | {'; '.join(verdicts) or 'as the reference'} |")
    print(f"| (reference) | 1e-12, 1e-11 | | | | {sum(int(float(row['steps'])) for row in reference)} | |")


def study_rides(binary, args, exceeded):
    """The rides' tables: against rtol, the presets, against the output step."""
    studied = cases()[:1] if args.quick else cases()

    references = {name: run(binary, path, sets, REFERENCE_RTOL) for name, path, sets in studied}
    if not args.presets:
        print("## Report numbers against rtol (atol = 10 rtol, both integrators); reference rtol 1e-12\n")
        print("| ride | rtol | worst relative error (which) | worst arc-length error, m (which) | ride steps | "
              "ride CPU s |")
        print("|---|---|---|---|---|---|")
    for name, path, sets in ([] if args.presets else studied):
        reference = references[name]
        for rtol in RTOLS:
            values = run(binary, path, sets, rtol)
            rel, rel_name, arc, arc_name = errors(values, reference)
            v = values["values"]
            print(f"| {name} | {rtol:.0e} | {rel:.1e} ({rel_name}) | {arc:.1e} ({arc_name}) | "
                  f"{v['ride_steps']} | {v['ride_cpu_time']:.3f} |")
        v = reference["values"]
        print(f"| {name} | 1e-12 (reference) | | | {v['ride_steps']} | {v['ride_cpu_time']:.3f} |")

    print("\n## The accuracy presets (&solver accuracy) against rtol 1e-12\n")
    print("| ride | accuracy | rtol, atol | worst relative error (which) | promised | "
          "worst arc-length error, m (which) | ride steps |")
    print("|---|---|---|---|---|---|---|")
    for name, path, sets in studied:
        reference = references[name]
        for preset, rtol, atol, bound in PRESETS:
            values = run(binary, path, sets, None, preset=preset)
            rel, rel_name, arc, arc_name = errors(values, reference)
            verdict = f"{bound:.0e}" + ("" if rel <= bound else " EXCEEDED")
            if rel > bound:
                exceeded.append(f"{name} at {preset}: {rel:.1e} > {bound:.0e}")
            print(f"| {name} | {preset} | {rtol:.0e}, {atol:.0e} | {rel:.1e} ({rel_name}) | {verdict} | "
                  f"{arc:.1e} ({arc_name}) | {values['values']['ride_steps']} |")

    if not args.presets:
        print("\n## Report numbers against the output step (rtol 1e-12); reference output step 0.0005 s\n")
        print("| ride | output step, s | worst relative error (which) | worst arc-length error, m (which) |")
        print("|---|---|---|---|")
    for name, path, sets in ([] if args.presets else studied):
        reference = run(binary, path, sets, REFERENCE_RTOL, 0.0005)
        for step in OUTPUT_STEPS:
            values = run(binary, path, sets, REFERENCE_RTOL, step)
            rel, rel_name, arc, arc_name = errors(values, reference)
            print(f"| {name} | {step:g} | {rel:.1e} ({rel_name}) | {arc:.1e} ({arc_name}) |")


if __name__ == "__main__":
    main()
