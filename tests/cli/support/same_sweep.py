#!/usr/bin/python3
"""Two sweeps' results are the same to the bit: every dataset under /sweep
(values and dtype; all but the wall-clock times, which differ from run to run,
and the numbers of threads and ranks, which are what differs)
and every CSV cell (all but the wall_time column).
usage: same_sweep.py A.h5 B.h5 A.csv B.csv; exit status 1 with the first difference."""
import csv
import sys

import h5py
import numpy as np


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and not name.endswith("wall_time") \
                    and name not in ("statistics/threads", "statistics/ranks"):
                out[name] = obj[()]
        f["/sweep"].visititems(visit)
    return out


def rows(path):
    with open(path, newline="") as f:
        table = list(csv.reader(f))
    drop = table[0].index("wall_time")
    return [r[:drop] + r[drop + 1:] for r in table]


def main():
    a, b = datasets(sys.argv[1]), datasets(sys.argv[2])
    if sorted(a) != sorted(b):
        print("different datasets:", sorted(set(a) ^ set(b)))
        return 1
    if len(a) < 40:
        print("too few datasets under /sweep:", len(a))
        return 1
    for name in sorted(a):
        x, y = np.asarray(a[name]), np.asarray(b[name])
        if x.dtype != y.dtype or x.shape != y.shape or x.tobytes() != y.tobytes():
            print(f"/sweep/{name} differs: {x!r} vs {y!r}")
            return 1
    ra, rb = rows(sys.argv[3]), rows(sys.argv[4])
    if ra != rb:
        for i, (p, q) in enumerate(zip(ra, rb)):
            if p != q:
                print(f"CSV row {i} differs:\n{p}\n{q}")
                break
        else:
            print("CSV: different numbers of rows", len(ra), len(rb))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
