#!/usr/bin/python3
"""Spline curves: slidesim's FITPACK (bench/fitpack_curves_bench.f90) next to the
genuine FITPACK through scipy (Debian python3-scipy 1.10.1) on the same data.

    /usr/bin/python3 bench/fitpack_curves_bench.py [path/to/fitpack_curves_bench]

1. splev: cubic spline interpolating 200 points of sin x + x/10 on [0, 10]
   (curfit / splrep, s = 0), evaluated at 10^6 sorted points;
2. a cubic 3-D curve interpolating 200 helix points (parcur / splprep, u given),
   at 10^6 parameters: ours point by point through spline_curve_t%evaluate and
   in one curev call; scipy's splev on the three coordinates;
3. curfit / splrep on 10^4 noisy points, s = m 0.05^2 / 2;
4. parcur (spline_curve_t%fit) / splprep on 10^4 noisy 3-D points, u given.
Times are the best of 5 runs. Checksums, numbers of knots and fp must agree.
"""
import os
import subprocess
import sys
import time

import numpy as np
import scipy
from scipy.interpolate import splev, splprep, splrep

REPEATS = 5


def best_of(f):
    best = float('inf')
    out = None
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return best, out


def scipy_side():
    res = {}
    m0, ne, mf = 200, 1000000, 10000
    x = 10 * np.arange(m0) / (m0 - 1)
    tck = splrep(x, np.sin(x) + 0.1 * x, k=3, s=0)
    xs = 10 * np.arange(ne) / (ne - 1)
    res['splev_1e6'], ys = best_of(lambda: splev(xs, tck, ext=3))
    res['splev_1e6_checksum'] = ys.sum()
    u = np.arange(m0) / (m0 - 1)
    pts = [np.cos(12 * u), np.sin(12 * u), 2 * u]
    (tckp, _), fp, ier, msg = splprep(pts, u=u, k=3, s=0, full_output=1, quiet=1)
    us = np.arange(ne) / (ne - 1)
    res['curve_eval_1e6'], xyz = best_of(lambda: splev(us, tckp, ext=3))
    res['curve_eval_1e6_checksum'] = sum(v.sum() for v in xyz)
    res['curev_1e6'] = res['curve_eval_1e6']
    res['curev_1e6_checksum'] = res['curve_eval_1e6_checksum']
    i = np.arange(mf)
    xf = 10 * i / (mf - 1)
    noise = 0.05 * np.sin(12345.678 * i)
    yf = np.sin(xf) + 0.1 * xf + noise
    s = mf * 0.05**2 / 2
    res['curfit_1e4'], out = best_of(lambda: splrep(xf, yf, k=3, s=s, full_output=1))
    (t, c, k), fp, ier, msg = out
    res['curfit_1e4_n'] = len(t)
    res['curfit_1e4_fp'] = fp
    res['curfit_1e4_ier'] = ier
    uf = i / (mf - 1)
    ptsf = [np.cos(12 * uf) + noise, np.sin(12 * uf) + noise, 2 * uf + noise]
    s3 = 3 * mf * 0.05**2 / 2
    res['parcur_1e4'], out = best_of(lambda: splprep(ptsf, u=uf, k=3, s=s3, full_output=1, quiet=1))
    (tck3, _), fp, ier, msg = out
    res['parcur_1e4_n'] = len(tck3[0])
    res['parcur_1e4_fp'] = fp
    return res


def ours(path):
    out = subprocess.run([path], check=True, capture_output=True, text=True).stdout
    res = {}
    for line in out.splitlines():
        key, value = line.split()
        res[key] = float(value)
    return res


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    default = os.path.join(here, '..', 'build', 'bench', 'fitpack_curves_bench')
    path = sys.argv[1] if len(sys.argv) > 1 else default
    a = ours(path)
    b = scipy_side()
    print('FITPACK curves: slidesim vs genuine FITPACK via scipy %s (best of %d)' % (scipy.__version__, REPEATS))
    print('%-44s %12s %12s %8s' % ('operation', 'ours [ms]', 'scipy [ms]', 'ratio'))
    names = [('splev_1e6', 'splev, cubic, 10^6 points'),
             ('curve_eval_1e6', '3-D cubic curve, 10^6 points (evaluate)'),
             ('curev_1e6', '3-D cubic curve, 10^6 points (curev)'),
             ('curfit_1e4', 'curfit, 10^4 noisy points, s > 0'),
             ('parcur_1e4', 'parcur, 10^4 noisy 3-D points, s > 0')]
    for key, label in names:
        print('%-44s %12.2f %12.2f %8.2f' % (label, 1e3 * a[key], 1e3 * b[key], a[key] / b[key]))
    print('agreement:')
    for key in ['splev_1e6_checksum', 'curve_eval_1e6_checksum', 'curev_1e6_checksum',
                'curfit_1e4_n', 'curfit_1e4_fp', 'curfit_1e4_ier', 'parcur_1e4_n', 'parcur_1e4_fp']:
        rel = abs(a[key] - b[key]) / max(abs(b[key]), 1e-300)
        print('  %-26s ours %-24.16g scipy %-24.16g rel. diff %.1e' % (key, a[key], b[key], rel))


if __name__ == '__main__':
    main()
