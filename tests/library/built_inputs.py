"""The shipped inputs each library test builds without io, from
tests/library/built_through_library.txt (one line each: the test, the
input). Read by check_library_coverage.py (what counts as built) and by the
tests themselves (compare_shipped.py, library_without_io.sh for
library_without_io, library_optimize and library_vehicle, shipped_geometries.sh), each of which fails unless its program built and
compared exactly the inputs given to it here (`check_built`).
"""
import os

BUILT = "tests/library/built_through_library.txt"
TESTS = ("shipped_descriptions", "library_without_io", "library_optimize", "library_vehicle", "shipped_geometries")


def read_built(path=None):
    """{input: (test, line number)} and the problems of the file."""
    path = path or os.path.join(os.path.dirname(os.path.abspath(__file__)), "built_through_library.txt")
    built, problems = {}, []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            fields = line.split()
            if len(fields) != 2 or fields[0] not in TESTS:
                problems.append(f"{BUILT}:{number}: '{line}': give the test ({', '.join(TESTS)}) and the input")
                continue
            test, input_path = fields
            if input_path in built:
                problems.append(f"{BUILT}:{number}: {input_path} is given twice (first on line "
                                f"{built[input_path][1]})")
                continue
            built[input_path] = (test, number)
    return built, problems


def inputs_of(test):
    """The inputs given to `test`, in the file's order."""
    built, problems = read_built()
    if problems:
        raise SystemExit("FAIL " + "\nFAIL ".join(problems))
    return [p for p, (t, _) in sorted(built.items(), key=lambda item: item[1][1]) if t == test]


def check_built(test, compared):
    """Failure lines unless `compared` (the inputs the test's program built
    and the test compared with the command's runs) is exactly the inputs
    given to `test`."""
    given = inputs_of(test)
    failures = [f"FAIL {test}: {p} is given to it in {BUILT} but its program built no description of it"
                for p in given if p not in compared]
    failures += [f"FAIL {test}: its program built {p}, which {BUILT} does not give to it: add the line"
                 for p in compared if p not in given]
    return failures
