#!/usr/bin/env python3
"""Every shipped input either goes through the library without io or is
listed, with the reason, in tests/library/not_yet_through_library.txt
(issue 24 point 2: "a test builds every shipped input through the library
without io").

    check_library_coverage.py      (run from the repository root)

An input counts as built through the library when
tests/library/built_through_library.txt gives it to one of the tests that
build shipped inputs from descriptions written in code (built_inputs.TESTS:
shipped_descriptions, library_without_io, library_optimize, library_vehicle,
shipped_geometries). Those tests
read the same file and fail unless their programs build and compare exactly
the inputs it gives them (library.built_inputs), so a line there is an input
really built, not a path named somewhere in a source (a comment, a message).
Fails, naming the file and the line, when an input is in neither list, in
both, not a shipped input, listed twice, or given to an unknown test. The
list of inputs not yet through the library may be empty (its comment only):
the check goes on guarding new inputs.
"""
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from built_inputs import BUILT, TESTS, read_built  # noqa: E402

TABLE = "tests/library/not_yet_through_library.txt"


def table_entries():
    entries, problems = {}, []
    with open(TABLE) as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            path, _, why = line.partition(" ")
            if not why.strip():
                problems.append(f"{TABLE}:{number}: {path} gives no reason (input, then one line why)")
            if path in entries:
                problems.append(f"{TABLE}:{number}: {path} is listed twice (first on line {entries[path]})")
            entries[path] = number
    return entries, problems


def main():
    shipped = sorted(glob.glob("inputs/*/*.nml"))
    if not shipped:
        print("FAIL no inputs/*/*.nml found: run from the repository root")
        return 1
    built, problems = read_built()
    listed, table_problems = table_entries()
    problems += table_problems
    for path in shipped:
        if path not in built and path not in listed:
            problems.append(f"{path}: built by no library test (not in {BUILT}) and not listed in {TABLE}: "
                            f"describe it in one of the tests ({', '.join(TESTS)}) and add its line to {BUILT}, "
                            "or list it with the reason")
        if path in built and path in listed:
            problems.append(f"{TABLE}:{listed[path]}: {path} is built through the library already "
                            f"({built[path][0]}, {BUILT}:{built[path][1]}): take its line out")
    for path, (test, number) in built.items():
        if path not in shipped:
            problems.append(f"{BUILT}:{number}: {path} is not a shipped input (inputs/*/*.nml)")
    for path, number in listed.items():
        if path not in shipped:
            problems.append(f"{TABLE}:{number}: {path} is not a shipped input (inputs/*/*.nml)")
    for problem in problems:
        print("FAIL " + problem)
    per_test = {t: sum(1 for p in shipped if p in built and built[p][0] == t) for t in TESTS}
    print(f"{len(shipped)} shipped inputs: {sum(p in built for p in shipped)} through the library "
          f"({', '.join(f'{t} {n}' for t, n in per_test.items())}), "
          f"{sum(p in listed for p in shipped)} listed as not yet")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
