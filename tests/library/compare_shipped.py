#!/usr/bin/env python3
"""Compares the shipped inputs built through the library without io
(shipped_descriptions, tests/library/shipped_descriptions.f90) with the
command's run of the same files: both over DURATION s (or over the duration
the library names for an input, its line `<input> duration <seconds>`: the
flights run their shipped durations, so that they land), the command's
numbers from --summary-json.

    compare_shipped.py SLIDESIM SHIPPED_DESCRIPTIONS

Run from the repository root. The two runs do the same arithmetic on the same
model when the descriptions say what the files say, so they agree to the
rounding of the JSON's decimal numbers (17 significant digits; the
tolerance, 1e-14 relative, is a few units of the last of them); the step and
right-hand-side counts agree exactly. Any other difference (a value copied
wrongly, a default the description misses, a builder doing otherwise than
the scenario) fails, naming the input, the number and both values. The
inputs built must be exactly those tests/library/built_through_library.txt
gives to shipped_descriptions (what check_library_coverage counts).
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from built_inputs import check_built  # noqa: E402

DURATION = "0.05"   # s: short, past the start's transients (several output steps)
RELATIVE = 1e-14


def main():
    slidesim, library = sys.argv[1], sys.argv[2]
    run = subprocess.run([library, DURATION], capture_output=True, text=True, timeout=1200)
    failures = [line for line in run.stdout.splitlines() if line.startswith("FAIL")]
    if run.returncode != 0 or failures:
        print(run.stdout + run.stderr)
        print(f"FAIL {library}: exit {run.returncode}")
        return 1
    expected = {}
    for line in run.stdout.splitlines():
        name, key, value = line.split()
        expected.setdefault(name, {})[key] = value
    listed = check_built("shipped_descriptions", list(expected))
    for line in listed:
        print(line)
    bad = len(listed)
    checked = 0
    with tempfile.TemporaryDirectory() as work:
        for name, values in expected.items():
            duration = values.pop("duration", DURATION)
            summary = os.path.join(work, "summary.json")
            cli = subprocess.run([slidesim, name, "-o", os.path.join(work, "result.h5"), "--summary-json", summary,
                                  "--set", f"solver%duration={float(duration)!r}"], capture_output=True, text=True,
                                 timeout=1200)
            if cli.returncode != 0:
                print(f"FAIL {name}: slidesim exit {cli.returncode}\n{cli.stdout}{cli.stderr}")
                bad += 1
                continue
            with open(summary) as f:
                got = {}
                for key, value in json.load(f)["values"].items():
                    if isinstance(value, list):   # a table (the landings): its rows' columns as table.row.column
                        for row, columns in enumerate(value, 1):
                            if not isinstance(columns, dict):   # a vector: key.row
                                got[f"{key}.{row}"] = columns
                                continue
                            for column, x in columns.items():
                                got[f"{key}.{row}.{column}"] = x
                    else:
                        got[key] = value
            before = bad
            for key, text in values.items():
                checked += 1
                if key not in got:
                    print(f"FAIL {name}: {key} is not in the command's summary")
                    bad += 1
                    continue
                if key in ("steps", "rhs_evaluations"):
                    same = int(text) == int(got[key])
                else:
                    a, b = float(text), float(got[key])
                    same = abs(a - b) <= RELATIVE * max(abs(a), abs(b))
                if not same:
                    print(f"FAIL {name}: {key}: library {text}, command {got[key]}")
                    bad += 1
            print(f"{'same' if bad == before else 'DIFF'} {name}: {len(values)} numbers")
    print(f"{checked} numbers of {len(expected)} inputs compared, {bad} differ")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
