#!/usr/bin/env bash
# The shipped inputs run through the library without io by PROGRAM
# (library_without_io.f90: the water, ride, sweep and identification inputs;
# library_optimize.f90: the optimisations; library_vehicle.f90: the vehicles'
# rides; descriptions filled in code) give
# the numbers the command's runs of the same inputs give (--summary-json of
# the fixture cli_every_input, tests/cli/support/every_input.sh: NAME.json
# per input, and a sweep's NAME.csv, a row per ride).
# Both compute the same operations from the same values, so the numbers
# must agree to the last digit and the step counts exactly; 1e-13 relative
# allows a rounding in a sum the compiler may order differently between the
# two programs, and nothing more (a wrong description, e.g. another
# friction, moves them by far more). A line `TEXT <input> <key> <words>`
# must be the summary's text under that key exactly, or with key `line` a
# line of the command's printed summary (NAME.out; the parts list). The
# inputs the program builds must be exactly those
# tests/library/built_through_library.txt gives to TEST (what
# check_library_coverage counts).
#
#     library_without_io.sh PROGRAM EVERY_INPUT_FOLDER [TEST]   (from the repository root;
#                                                              TEST: library_without_io)
set -u
program=$1
results=$2
test=${3:-library_without_io}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$program" > "$work/library.txt" || { echo "FAIL $program: $(tail -3 "$work/library.txt")"; exit 1; }
python=/usr/bin/python3
command -v "$python" >/dev/null || python=python3
"$python" - "$work/library.txt" "$results" "$test" <<'PY'
import csv, json, os, sys
sys.path.insert(0, "tests/library")
from built_inputs import check_built

COUNTS = {"steps", "rhs_evaluations", "ride_steps", "flights", "whole_flights", "landings", "inlets_joined",
          "limits_exceeded", "rides", "complete", "waters", "rides_over_limit",
          "evaluations", "restarts", "population_size", "parts", "elements"}
library, texts = {}, {}
for line in open(sys.argv[1]):
    if line.startswith("TEXT "):
        _, path, key, words = line.rstrip("\n").split(" ", 3)
        texts.setdefault(path, []).append((key, words))
        library.setdefault(path, {})
        continue
    path, key, value = line.split()
    library.setdefault(path, {})[key] = float(value)
failures = check_built(sys.argv[3], list(library))
for failure in failures:
    print(failure)
failures = len(failures)
for path, numbers in library.items():
    name = path[len("inputs/"):-len(".nml")].replace("/", "_")
    summary = os.path.join(sys.argv[2], name + ".json")
    command = {}
    for key, value in json.load(open(summary))["values"].items():
        if isinstance(value, list):   # a table: its rows' columns as table.row.column
            for row, columns in enumerate(value, 1):
                if not isinstance(columns, dict):   # a vector: key.row
                    command[f"{key}.{row}"] = columns
                    continue
                for column, x in columns.items():
                    command[f"{key}.{row}.{column}"] = x
        else:
            command[key] = value
    table = os.path.join(sys.argv[2], name + ".csv")   # a sweep's rides: a row each, as rides.row.column
    if os.path.exists(table):
        for row in csv.DictReader(open(table)):
            for column, text in row.items():
                try:
                    command[f"rides.{row['ride']}.{column}"] = float(text)
                except ValueError:
                    pass
    if len(numbers) < 10:
        print(f"FAIL {path}: the library program printed only {numbers}")
        failures += 1
        continue
    before = failures
    words = {key: value for key, value in json.load(open(summary))["values"].items() if isinstance(value, str)}
    printed = [line.strip() for line in open(os.path.join(sys.argv[2], name + ".out"))]
    for key, text in texts.get(path, []):
        if key == "line" and text not in printed:
            print(f"FAIL {path}: the command's summary has no line '{text}'")
            failures += 1
        elif key != "line" and words.get(key) != text:
            print(f"FAIL {path} {key}: library '{text}', command '{words.get(key)}'")
            failures += 1
    for key, value in numbers.items():
        if key not in command:
            print(f"FAIL {path} {key}: not in the command's summary {summary}")
            failures += 1
        elif key in COUNTS and value != command[key]:
            print(f"FAIL {path} {key}: library {value!r}, command {command[key]!r}")
            failures += 1
        elif abs(value - command[key]) > 1e-13 * abs(command[key]):
            print(f"FAIL {path} {key}: library {value!r}, command {command[key]!r}")
            failures += 1
    print(f"{'same' if failures == before else 'DIFF'} {path}: {len(numbers)} numbers and "
          f"{len(texts.get(path, []))} texts compared with {summary}")
sys.exit(1 if failures else 0)
PY
