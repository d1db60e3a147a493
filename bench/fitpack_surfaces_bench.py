#!/usr/bin/python3
"""Bicubic surface, value and all partials to third order at 10^6 points:
slidesim's spline_surface_t (bench/fitpack_surfaces_bench.f90) next to the
genuine FITPACK through scipy (Debian python3-scipy 1.10.1) on the same spline
and points.

    /usr/bin/python3 bench/fitpack_surfaces_bench.py [path/to/fitpack_surfaces_bench]

The spline interpolates (s = 0, unique) z = sin(3x) cos(2y) + x y on a 40 x 30
grid of [0,1] x [0,2] (regrid through RectBivariateSpline). scipy needs one call
per partial: bisplev(x, y, tck, dx, dy) on the 1000 x 1000 grid (FITPACK's
bispev/parder, B-splines computed once per grid line) and
RectBivariateSpline.ev(x, y, dx, dy) on 10^6 scattered points (bispeu/pardeu).
FITPACK's parder cannot give z_xxx and z_yyy of a bicubic (nux < kx), so scipy
makes eight calls and ours one call giving all ten partials; checksums (sum of
the eight common partials over all points) must agree.
"""
import os
import subprocess
import sys
import time

import numpy as np
import scipy
from scipy.interpolate import RectBivariateSpline, bisplev

# FITPACK's parder needs nux < kx and nuy < ky: for a bicubic it cannot give
# z_xxx and z_yyy, so scipy is timed on the other eight partials (ours on all ten)
ORDERS = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (2, 1), (1, 2)]


def halton(n, base):
    i = np.arange(1, n + 1)
    h = np.zeros(n)
    f = np.ones(n)
    while np.any(i > 0):
        f = f / base
        h = h + f * (i % base)
        i = i // base
    return h


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
    t0 = time.perf_counter()
    total = 0.0
    for dx, dy in ORDERS:
        total += bisplev(xg, yg, tck, dx, dy).sum()
    t_grid = time.perf_counter() - t0
    xs = halton(npts, 2)
    ys = 2 * halton(npts, 3)
    t0 = time.perf_counter()
    total_s = 0.0
    for dx, dy in ORDERS:
        total_s += spl.ev(xs, ys, dx=dx, dy=dy).sum()
    t_scat = time.perf_counter() - t0
    rows = {"grid1000x1000": [t_grid, total], "scattered1e6": [t_scat, total_s]}
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
    print("bicubic surface, 10^6 points: ours value + 9 partials (one call per point); "
          "scipy %s value + 7 partials (8 calls)" % scipy.__version__)
    print("%-16s %12s %12s %8s  %-24s %-24s" % ("case", "ours [s]", "scipy [s]", "ratio", "checksum ours", "checksum scipy"))
    rows["grid_by_lines"] = rows["grid1000x1000"]
    for case, (ts, cs) in rows.items():
        if case in ours:
            to, co = ours[case]
            print("%-16s %12.4f %12.4f %8.2f  %-24.15e %-24.15e" % (case, to, ts, to / ts, co, cs))
        else:
            print("%-16s %12s %12.4f %8s  %-24s %-24.15e" % (case, "-", ts, "-", "-", cs))


if __name__ == "__main__":
    main()
