#!/usr/bin/env bash
# The shipped water and ride inputs through the library without io
# (library_without_io.f90, descriptions filled in code) give the numbers the
# command's runs of the same inputs give (--summary-json of the fixture
# cli_every_input: water_demo_slide, ride_demo_slide). Both compute the same
# operations from the same values, so the numbers must agree to the last
# digit; 1e-13 relative allows a rounding in a sum the compiler may order
# differently between the two programs, and nothing more (a wrong
# description, e.g. another friction, moves them by far more).
#
#     library_without_io.sh PROGRAM EVERY_INPUT_FOLDER
set -u
program=$1
results=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$program" > "$work/library.txt" || { echo "FAIL $program: $(tail -3 "$work/library.txt")"; exit 1; }
python=/usr/bin/python3
command -v "$python" >/dev/null || python=python3
"$python" - "$work/library.txt" "$results/water_demo_slide.json" "$results/ride_demo_slide.json" <<'PY'
import json, sys
library = {}
for line in open(sys.argv[1]):
    scenario, key, value = line.split()
    library.setdefault(scenario, {})[key] = float(value)
failures = 0
for scenario, path in (('water', sys.argv[2]), ('ride', sys.argv[3])):
    command = json.load(open(path))['values']
    if scenario not in library or len(library[scenario]) < 10:
        print(f"FAIL {scenario}: the library program printed {library.get(scenario)}")
        failures += 1
        continue
    for key, value in library[scenario].items():
        if key not in command:
            print(f"FAIL {scenario} {key}: not in the command's summary {path}")
            failures += 1
        elif abs(value - command[key]) > 1e-13 * abs(command[key]):
            print(f"FAIL {scenario} {key}: library {value!r}, command {command[key]!r}")
            failures += 1
    print(f"{scenario}: {len(library[scenario])} numbers compared")
sys.exit(1 if failures else 0)
PY
