#!/usr/bin/env python3
"""Every shipped input either goes through the library without io or is
listed, with the reason, in tests/library/not_yet_through_library.txt
(issue 24 point 2: "a test builds every shipped input through the library
without io").

    check_library_coverage.py      (run from the repository root)

An input counts as built through the library when one of the tests that
build shipped inputs from descriptions written in code names it in its
sources (tests/library/shipped_descriptions.f90 and library_without_io.f90,
tests/geometry/shipped_geometries.f90 and .sh; a pattern such as
inputs/geometry/*.nml there counts for every file it matches). Fails, naming
the file, when an input is in neither place, when a listed input is covered
already (the table is stale: take its line out), when a listed input does
not exist, or when the table lists one twice.
"""
import glob
import re
import sys

SOURCES = ["tests/library/shipped_descriptions.f90", "tests/library/library_without_io.f90",
           "tests/geometry/shipped_geometries.f90", "tests/geometry/shipped_geometries.sh"]
TABLE = "tests/library/not_yet_through_library.txt"
NAMED = re.compile(r"inputs/[a-z_0-9]+/(?:[a-z_0-9]+|\*)\.nml")


def covered_inputs():
    covered = {}
    for source in SOURCES:
        with open(source) as f:
            text = f.read()
        for pattern in NAMED.findall(text):
            for path in glob.glob(pattern):
                covered.setdefault(path, source)
    return covered


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
    covered = covered_inputs()
    listed, problems = table_entries()
    for path in shipped:
        if path not in covered and path not in listed:
            problems.append(f"{path}: built by no library test ({', '.join(SOURCES)}) and not listed in {TABLE}: "
                            "describe it in one of those tests, or list it with the reason")
        if path in covered and path in listed:
            problems.append(f"{TABLE}:{listed[path]}: {path} is built through the library already "
                            f"({covered[path]}): take its line out")
    for path, number in listed.items():
        if path not in shipped:
            problems.append(f"{TABLE}:{number}: {path} is not a shipped input (inputs/*/*.nml)")
    for problem in problems:
        print("FAIL " + problem)
    print(f"{len(shipped)} shipped inputs: {sum(p in covered for p in shipped)} through the library, "
          f"{sum(p in listed for p in shipped)} listed as not yet")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
