#!/usr/bin/python3
"""Bicubic surface, value and partials to third order at 10^6 points:
slidesim's spline_surface_t (bench/fitpack_surfaces_bench.f90) next to the
genuine FITPACK through scipy (Debian python3-scipy 1.10.1) on the same spline
and points.

    /usr/bin/python3 bench/fitpack_surfaces_bench.py [path/to/fitpack_surfaces_bench]

The spline interpolates (s = 0, unique) z = sin(3x) cos(2y) + x y on a 40 x 30
grid of [0,1] x [0,2] (regrid through RectBivariateSpline).

What each side computes (every time is the median of 5 runs and includes
summing the results into the checksum):
  ours   one call per point (evaluate) or per grid (evaluate_grid) giving ten
         quantities: z and all nine partials to third order. There is no
         cheaper mode; ours always computes all ten.
  scipy  one call per quantity: bisplev(x, y, tck, dx, dy) on the 1000 x 1000
         grid (FITPACK bispev/parder: B-splines once per grid line) and
         RectBivariateSpline.ev(x, y, dx, dy) at 10^6 scattered points
         (bispeu/pardeu). parder needs nux < kx and nuy < ky, so for a bicubic
         scipy cannot give z_xxx and z_yyy: it is timed on the other eight.
So scipy's measured time covers 8 quantities and ours 10; the column
"scipy x10/8" scales scipy to ten quantities at its cost per quantity (an
estimate, not a measurement). "ratio" divides ours by the measured scipy time
(8 quantities), the comparison least favourable to ours. The checksum is the
sum of the eight common quantities over all points; it agrees between the
sides to summation-order rounding (~1e-13 relative).
"""
import os
import subprocess
import sys
import time

import numpy as np
import scipy
from scipy.interpolate import RectBivariateSpline, bisplev

# the eight (dx, dy) parder can give for a bicubic (not (3, 0), (0, 3))
ORDERS = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (2, 1), (1, 2)]
NREP = 5


def halton(n, base):
    i = np.arange(1, n + 1)
    h = np.zeros(n)
    f = np.ones(n)
    while np.any(i > 0):
        f = f / base
        h = h + f * (i % base)
        i = i // base
    return h


def median_time(fn):
    times, total = [], None
    for _ in range(NREP):
        t0 = time.perf_counter()
        total = fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), total


def main():
    mx, my, ng, npts = 40, 30, 1000, 1000000
    x = np.linspace(0.0, 1.0, mx)
    y = 2.0 * np.linspace(0.0, 1.0, my)
    X, Y = np.meshgrid(x, y, indexing="ij")
    z = np.sin(3 * X) * np.cos(2 * Y) + X * Y
    spl = RectBivariateSpline(x, y, z, kx=3, ky=3, s=0)
    tck = list(spl.tck) + [3, 3]
    xg = (np.arange(1, ng + 1) - 0.5) / ng
    yg = 2 * (np.arange(1, ng + 1) - 0.5) / ng
    xs = halton(npts, 2)
    ys = 2 * halton(npts, 3)

    def grid():
        return sum(bisplev(xg, yg, tck, dx, dy).sum() for dx, dy in ORDERS)

    def scattered():
        return sum(spl.ev(xs, ys, dx=dx, dy=dy).sum() for dx, dy in ORDERS)

    scipy_grid = median_time(grid)
    scipy_scat = median_time(scattered)
    exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join("build", "bench", "fitpack_surfaces_bench")
    ours = {}
    if os.path.exists(exe):
        out = subprocess.run([exe], capture_output=True, text=True, check=True).stdout
        for line in out.splitlines():
            parts = line.split()
            if len(parts) == 4 and parts[0] == "ours":
                ours[parts[1]] = (float(parts[2]), float(parts[3]))
    else:
        print("(Fortran bench not found at %s: build target fitpack_surfaces_bench)" % exe)
    # our case -> (what ours does, the scipy measurement it is compared with)
    cases = [
        ("grid_pointwise", "1000x1000 grid, evaluate per point", scipy_grid),
        ("grid_one_call", "1000x1000 grid, one evaluate_grid", scipy_grid),
        ("grid_by_lines", "1000x1000 grid, evaluate_grid per line", scipy_grid),
        ("scattered1e6", "10^6 scattered points, evaluate", scipy_scat),
    ]
    print("bicubic surface, 10^6 points, medians of %d runs; scipy %s" % (NREP, scipy.__version__))
    print("ours: 10 quantities per point (z + 9 partials, one call); "
          "scipy: 8 quantities (8 calls; z_xxx, z_yyy unavailable)")
    print("scipy grid cases: bisplev on the whole grid; scipy scattered: RectBivariateSpline.ev")
    print("%-15s %-40s %9s %9s %11s %7s %10s" % ("case", "ours does", "ours [s]", "scipy [s]",
                                               "scipy x10/8", "ratio", "checksum"))
    for case, what, (ts, cs) in cases:
        if case in ours:
            to, co = ours[case]
            agree = "%.1e" % (abs(co - cs) / abs(cs))
            print("%-15s %-40s %9.4f %9.4f %11.4f %7.2f %10s" % (case, what, to, ts, ts * 10 / 8, to / ts, agree))
        else:
            print("%-15s %-40s %9s %9.4f %11.4f %7s %10s" % (case, what, "-", ts, ts * 10 / 8, "-", "-"))
    print("ratio = ours / scipy (measured, 8 quantities); checksum = relative difference of the sums")


if __name__ == "__main__":
    main()
