"""Each plot script writes a PNG of a result of its scenario (-o), and
refuses a result of another scenario and a file that is not a result, with
exit status 1 and a message naming the file and what it is. All scripts run
in this one process (runpy, sys.argv set per call, as `python3 script`
would), so matplotlib is imported once.

    check_plot_scripts.py SCRIPTS WORK WRONG_KIND.h5 OTHER_KIND.h5 TEXT_FILE KIND=SCENARIO ...

KIND names scripts/plot_KIND.py (a thin call of slidesim.plot), SCENARIO the scenario of its own results,
WORK/KIND.h5 is such a result and WORK/KIND.png the picture written;
WRONG_KIND.h5 is a result of another scenario than any KIND's except one,
for which OTHER_KIND.h5 (of another scenario) is used. Prints failures; exit
status 1 if any.
"""
import contextlib
import io
import os
import runpy
import sys
import tempfile

import h5py
import matplotlib

matplotlib.use("Agg")   # as in CI: no window
import matplotlib.pyplot as plt  # noqa: E402


def run(script, argv):
    """Runs a script as __main__; returns (exit status, what it printed)."""
    out = io.StringIO()
    sys.argv = [script] + argv
    status = 0
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        try:
            runpy.run_path(script, run_name="__main__")
        except SystemExit as stop:
            if isinstance(stop.code, str):
                print(stop.code)
                status = 1
            else:
                status = stop.code or 0
        except Exception as error:   # a script that went on and broke is a failure too
            print(f"{type(error).__name__}: {error}")
            status = "exception"
    return status, out.getvalue()


def main(scripts, work, wrong, other, text, *kinds):
    failures = 0
    sys.path.insert(0, scripts)   # as when a script runs: its own folder first
    scenario_of = {path: h5py.File(path, "r").attrs["scenario"] for path in (wrong, other)}
    for entry in kinds:
        kind, scenario = entry.split("=")
        script = os.path.join(scripts, f"plot_{kind}.py")
        picture = os.path.join(work, f"{kind}.png")
        status, said = run(script, [os.path.join(work, f"{kind}.h5"), "-o", picture])
        plt.close("all")
        if status != 0:
            print(f"FAIL plot_{kind}.py: status {status}: {said}")
            failures += 1
        elif open(picture, "rb").read(8) != b"\x89PNG\r\n\x1a\n":
            print(f"FAIL plot_{kind}.py: {picture} is not a PNG")
            failures += 1
        elif os.path.getsize(picture) < 20000:
            print(f"FAIL plot_{kind}.py: {picture} is almost empty")
            failures += 1
        result = wrong if scenario_of[wrong] != scenario else other
        with tempfile.TemporaryDirectory() as folder:
            status, said = run(script, [result, "-o", os.path.join(folder, "wrong.png")])
        if status != 1 or f"a '{scenario_of[result]}' result" not in said:
            print(f"FAIL plot_{kind}.py on a {scenario_of[result]} result: status {status}, said {said!r}")
            failures += 1
        status, said = run(script, [text])
        if status != 1 or f"{os.path.basename(text)}: not an HDF5 file" not in said:
            print(f"FAIL plot_{kind}.py on a text file: status {status}, said {said!r}")
            failures += 1
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main(*sys.argv[1:])
