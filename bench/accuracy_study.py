#!/usr/bin/env python3
"""How the ride report's numbers converge with the integrator's tolerances.

Usage: bench/accuracy_study.py BUILD [--quick] [--csv FILE]

For every shipped ride (inputs/default.nml, inputs/ride/demo_slide.nml) and
the two riders of the shipped sweep (inputs/sweep/demo_population.nml) on the
default slide, the ride is run
with both integrators (the rider's &solver and the water's &water_solver) at
rtol = 1e-4 ... 1e-11 (atol = 10 rtol, as the shipped 1e-10 / 1e-9) and
compared with a reference at rtol = 1e-12. Each number of the JSON summary
(`--summary-json`) is compared:
  - values in the summary's own unit: relative error |x - ref| / |ref|
    (forces, speeds, felt g, angles, distances, times);
  - the arc lengths where an extreme happens: absolute error in m (an extreme
    with two near-equal peaks may move between them; that is reported, not
    hidden).
A second part keeps rtol = 1e-12 and varies the output step (0.01 s shipped):
the report's maxima and minima are located between the records on the
integrator's dense output, so the output step should not limit them (before
they were taken over the records and were good only to the record spacing).

The tables it prints are the ones in docs/accuracy.md (made with a Release
build; re-run it to check them).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTOLS = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11]
REFERENCE_RTOL = 1e-12
OUTPUT_STEPS = [0.01, 0.005, 0.002, 0.001]
SKIP = {"ride_cpu_time", "water_cpu_time", "ride_steps"}


def cases():
    """(name, input, --set arguments) of the rides studied: the shipped rides,
    and the two riders of the shipped sweep (inputs/sweep/demo_population.nml,
    paired: female 50 kg 1.60 m at 4 l/s, male 100 kg 1.90 m at 6 l/s) on the
    default slide."""
    default = os.path.join(ROOT, "inputs/default.nml")
    return [
        ("default", default, []),
        ("ride/demo_slide", os.path.join(ROOT, "inputs/ride/demo_slide.nml"), []),
        ("female 50 kg", default, ["rider%sex=female", "rider%mass=50", "rider%height=1.6",
                                   "water%flow_rate=0.004"]),
        ("male 100 kg", default, ["rider%sex=male", "rider%mass=100", "rider%height=1.9",
                                  "water%flow_rate=0.006"]),
    ]


def run(binary, path, sets, rtol, output_step=None):
    atol = 10 * rtol
    with tempfile.TemporaryDirectory() as tmp:
        summary = os.path.join(tmp, "s.json")
        args = [binary, "-q", "-o", os.path.join(tmp, "r.h5"), "--summary-json", summary]
        for group in ("solver", "water_solver"):
            args += ["--set", f"{group}%rtol={rtol:g}", "--set", f"{group}%atol={atol:g}"]
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
        elif ref != 0:
            e = abs(x - ref) / abs(ref)
            if e > worst_rel:
                worst_rel, worst_rel_name = e, name
    return worst_rel, worst_rel_name, worst_arc, worst_arc_name


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", help="a build folder holding slidesim")
    parser.add_argument("--quick", action="store_true", help="only the default ride")
    args = parser.parse_args()
    binary = os.path.join(args.build, "slidesim")
    if not os.access(binary, os.X_OK):
        sys.exit(f"accuracy_study: no slidesim in {args.build}")
    studied = cases()[:1] if args.quick else cases()

    print("## Report numbers against rtol (atol = 10 rtol, both integrators); reference rtol 1e-12\n")
    print("| ride | rtol | worst relative error (which) | worst arc-length error, m (which) | ride steps | ride CPU s |")
    print("|---|---|---|---|---|---|")
    for name, path, sets in studied:
        reference = run(binary, path, sets, REFERENCE_RTOL)
        for rtol in RTOLS:
            values = run(binary, path, sets, rtol)
            rel, rel_name, arc, arc_name = errors(values, reference)
            v = values["values"]
            print(f"| {name} | {rtol:.0e} | {rel:.1e} ({rel_name}) | {arc:.1e} ({arc_name}) | "
                  f"{v['ride_steps']} | {v['ride_cpu_time']:.3f} |")
        v = reference["values"]
        print(f"| {name} | 1e-12 (reference) | | | {v['ride_steps']} | {v['ride_cpu_time']:.3f} |")

    print("\n## Report numbers against the output step (rtol 1e-12); reference output step 0.0005 s\n")
    print("| ride | output step, s | worst relative error (which) | worst arc-length error, m (which) |")
    print("|---|---|---|---|")
    for name, path, sets in studied:
        reference = run(binary, path, sets, REFERENCE_RTOL, 0.0005)
        for step in OUTPUT_STEPS:
            values = run(binary, path, sets, REFERENCE_RTOL, step)
            rel, rel_name, arc, arc_name = errors(values, reference)
            print(f"| {name} | {step:g} | {rel:.1e} ({rel_name}) | {arc:.1e} ({arc_name}) |")


if __name__ == "__main__":
    main()
