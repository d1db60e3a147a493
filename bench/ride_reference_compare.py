#!/usr/bin/python3
"""Largest differences of rides against a reference ride (bench/README.md, "The ride").

A speed change that moves the trajectory at integration-noise level is judged
by how close its ride stays to a converged reference: the same input at rtol
1e-13, atol 1e-12 (&solver). Compares the output records (record_kind 2) at the
times both files have.

usage: bench/ride_reference_compare.py reference.h5 ride.h5 [ride.h5 ...]
"""
import sys

import h5py
import numpy as np

QUANTITIES = [
    ("pelvis arc length, m", "rider/pelvis/arc_length"),
    ("speed, m/s", "rider/speed"),
    ("pelvis normal force, N", "rider/pelvis/normal_force"),
    ("heels normal force, N", "rider/heels/normal_force"),
    ("heading, rad", "rider/heading"),
    ("energy, J", "rider/energy"),
]


def outputs(path):
    with h5py.File(path, "r") as f:
        kind = f["rider/record_kind"][...]
        keep = kind == 2
        data = {name: f[name][...][keep] for _, name in QUANTITIES}
        data["time"] = f["rider/time"][...][keep]
        data["end"] = f["rider/time"][-1]
        data["steps"] = int(f["rider/statistics/steps"][()])
    return data


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    ref = outputs(argv[1])
    for path in argv[2:]:
        run = outputs(path)
        common, i_ref, i_run = np.intersect1d(np.round(ref["time"], 9), np.round(run["time"], 9),
                                              return_indices=True)
        print(f"{path}: {run['steps']} steps, {len(common)} common outputs")
        for label, name in QUANTITIES:
            d = np.max(np.abs(run[name][i_run] - ref[name][i_ref]))
            print(f"  {label:28s} {d:.2e}")
        print(f"  {'end time, s':28s} {abs(run['end'] - ref['end']):.2e}")


if __name__ == "__main__":
    main(sys.argv)
