#!/usr/bin/python3
"""Reference tables for slidesim's FITPACK surface routines (surfit, regrid,
bispev, parder) from the genuine Fortran FITPACK in Debian's python3-scipy 1.10.1.

Run with /usr/bin/python3 from the repository root:
    /usr/bin/python3 scripts/reference/fitpack_surfaces.py
Writes tests/reference/fitpack/surfaces_{regrid,eval,surfit}.txt.

Table format (the curve tables' one, read by
external/fitpack/tests/support/fitpack_reference_io.f90): '#' lines are
comments; 'case <name>' ... 'end' holds one case; inside, '<key> <count>' is
followed by <count> numbers. Reals are written as Python repr (17 significant
digits), so they read back exactly.

Entry points (scipy 1.10.1, genuine netlib Fortran compiled double precision):
  surfit  -> scipy.interpolate.dfitpack.surfit_smth (iopt=0) and surfit_lsq
             (iopt=-1), bisplrep(task=1) for iopt=1; bbox and nxest/nyest
             always given explicitly;
  regrid  -> dfitpack.regrid_smth (iopt=0, nxest=mx+kx+1, nyest=my+ky+1);
  bispev  -> dfitpack.bispev;  parder -> dfitpack.parder.
"""
import os
import sys

import numpy as np
import scipy
from scipy.interpolate import bisplrep, dfitpack

OUT = os.path.join("tests", "reference", "fitpack")


FILES = {}


def header(group):
    return [
        "# slidesim FITPACK surface reference tables: " + group,
        "# made by scripts/reference/fitpack_surfaces.py with scipy %s "
        "(Debian python3-scipy, genuine Fortran FITPACK, double precision), numpy %s"
        % (scipy.__version__, np.__version__),
        "# format: 'case <name>' ... 'end'; inside, '<key> <count>' then <count> numbers,",
        "# one per line (reals as Python repr: exact round trip; integers as integers).",
    ]


class Table:
    """One case; cases are grouped into files surfaces_<group>.txt by name prefix."""

    def __init__(self, name, description):
        self.group = name.split("_")[0]
        self.name = name
        self.lines = ["#", "# " + name + ":"]
        for line in description.strip().splitlines():
            self.lines.append("#   " + line.strip())
        self.lines.append("case " + name)

    def int(self, name, values):
        vals = np.atleast_1d(np.asarray(values)).ravel()
        self.lines.append("%s %d" % (name, vals.size))
        self.lines.extend("%d" % int(v) for v in vals)

    def real(self, name, values):
        vals = np.atleast_1d(np.asarray(values, dtype=float)).ravel()
        self.lines.append("%s %d" % (name, vals.size))
        self.lines.extend(repr(float(v)) for v in vals)

    def write(self):
        FILES.setdefault(self.group, header(self.group))
        FILES[self.group].extend(self.lines + ["end"])


def write_files():
    for group, lines in FILES.items():
        path = os.path.join(OUT, "surfaces_%s.txt" % group)
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        print("wrote", path)


def grid_data(mx, my, seed, noise, bbox=(0.0, 1.0, 0.0, 1.0), uneven=False):
    rng = np.random.default_rng(seed)
    xb, xe, yb, ye = bbox
    x = np.linspace(xb, xe, mx)
    y = np.linspace(yb, ye, my)
    if uneven:
        x[1:-1] += (rng.random(mx - 2) - 0.5) * 0.5 * (xe - xb) / (mx - 1)
        y[1:-1] += (rng.random(my - 2) - 0.5) * 0.5 * (ye - yb) / (my - 1)
    X, Y = np.meshgrid(x, y, indexing="ij")
    z = np.sin(2.0 * X + 0.5) * np.cos(1.5 * Y) + 0.3 * X * Y
    z = z + noise * rng.standard_normal(z.shape)
    return x, y, z


def regrid_case(name, description, mx, my, kx, ky, s, seed, noise, bbox_data=(0, 1, 0, 1),
                bbox=None, uneven=False, duplicate=False):
    x, y, z = grid_data(mx, my, seed, noise, bbox_data, uneven)
    if duplicate:
        x[3] = x[2]
    if bbox is None:
        bbox = (x[0], x[-1], y[0], y[-1])
    return regrid_data_case(name, description, x, y, z, bbox, kx, ky, s)


def regrid_data_case(name, description, x, y, z, bbox, kx, ky, s, ier_expected=None):
    mx, my = len(x), len(y)
    xb, xe, yb, ye = bbox
    nx, tx, ny, ty, c, fp, ier = dfitpack.regrid_smth(x, y, z.ravel(), xb, xe, yb, ye, kx, ky, s)
    if ier_expected is not None:
        assert ier == ier_expected, (name, ier, ier_expected)
    t = Table("regrid_" + name, description +
              "\nregrid iopt=0 through dfitpack.regrid_smth: nxest=mx+kx+1, nyest=my+ky+1")
    t.int("kx", kx); t.int("ky", ky)
    t.real("s", s); t.real("bbox", [xb, xe, yb, ye])
    t.int("nxest", mx + kx + 1); t.int("nyest", my + ky + 1)
    t.real("x", x); t.real("y", y); t.real("z", z.ravel())
    t.int("ier", ier); t.real("fp", fp)
    t.real("tx", tx[:nx]); t.real("ty", ty[:ny])
    t.real("c", c[:(nx - kx - 1) * (ny - ky - 1)])
    t.write()
    return tx[:nx], ty[:ny], c[:(nx - kx - 1) * (ny - ky - 1)]


# ---- regrid ier = 2 and 3 -------------------------------------------------------
# The p-iteration gives up (ier = 3: maxit = 20 reached; ier = 2: f(p) out of the
# order theory promises) only for particular data and s. Such cases were found by
# a random search over small grids (run `fitpack_surfaces.py --search-regrid`:
# it prints seed, trial and ier); the draws below replay trial `trial` of seed
# `seed` without calling FITPACK for the earlier trials, so the table needs no
# search. (Some random grids crash scipy 1.10.1's regrid_smth outright: the search
# runs every call in a forked child.)
def regrid_search_draw(search, lo):
    mx = int(search.randint(5, 14))
    my = int(search.randint(5, 14))
    kx = int(search.randint(1, 6))
    ky = int(search.randint(1, 6))
    x = np.sort(search.uniform(0, 1, mx))
    y = np.sort(search.uniform(0, 1, my))
    z = search.normal(0, 1, (mx, my)) * 10 ** search.uniform(-3, 3)
    rounded = search.rand() < 0.5
    srel = 10.0 ** search.uniform(lo, 0)
    usable = mx > kx and my > ky and np.all(np.diff(x) > 1e-3) and np.all(np.diff(y) > 1e-3)
    if rounded:
        z = np.round(z, 0)
    return usable, x, y, z, kx, ky, srel * np.sum(z ** 2)


def regrid_replay(seed, lo, trial):
    search = np.random.RandomState(seed)
    for _ in range(trial + 1):
        draw = regrid_search_draw(search, lo)
    assert draw[0]
    return draw[1:]


def regrid_sensitivity(x, y, z, kx, ky, s, samples=8):
    """Largest relative change of fp (and of the coefficients) when z is perturbed
    at 1e-15 relative: a case the genuine FITPACK itself cannot reproduce to 1e-8
    under such perturbations is rounding-chaotic and unfit as a reference."""
    def fit(zz):
        nx, tx, ny, ty, c, fp, ier = dfitpack.regrid_smth(x, y, zz.ravel(), x[0], x[-1], y[0], y[-1], kx, ky, s)
        return nx, ny, c[:(nx - kx - 1) * (ny - ky - 1)], fp, ier
    nx0, ny0, c0, fp0, ier0 = fit(z)
    pert = np.random.RandomState(99)
    dfp = dc = 0.0
    for _ in range(samples):
        nx, ny, c, fp, ier = fit(z * (1 + 1e-15 * pert.uniform(-1, 1, z.shape)))
        if (nx, ny, ier) != (nx0, ny0, ier0):
            return ier0, np.inf, np.inf
        dfp = max(dfp, abs(fp - fp0) / abs(fp0))
        big = np.abs(c0) > 1e-8 * np.max(np.abs(c0))
        if np.any(big):
            dc = max(dc, np.max(np.abs(c - c0)[big] / np.abs(c0[big])))
    return ier0, dfp, dc


def regrid_search(seeds=range(1, 6), lo=-14.0, trials=4000):
    import pickle

    def forked(args):
        r, w = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(r)
            ier = dfitpack.regrid_smth(args[0], args[1], args[2].ravel(), args[0][0], args[0][-1],
                                       args[1][0], args[1][-1], *args[3:])[-1]
            out = regrid_sensitivity(*args) if ier in (1, 2, 3) else (ier, 0.0, 0.0)
            with os.fdopen(w, "wb") as f:
                f.write(pickle.dumps(out))
            os._exit(0)
        os.close(w)
        with os.fdopen(r, "rb") as f:
            data = f.read()
        os.waitpid(pid, 0)
        return pickle.loads(data) if data else (None, 0.0, 0.0)

    for seed in seeds:
        search = np.random.RandomState(seed)
        for trial in range(trials):
            usable, x, y, z, kx, ky, s = regrid_search_draw(search, lo)
            if not usable:
                continue
            ier, dfp, dc = forked((x, y, z, kx, ky, s))
            if ier in (1, 2, 3):
                print("seed", seed, "trial", trial, "ier", ier, "mx my kx ky", len(x), len(y), kx, ky,
                      "s/sum z^2 %.3g" % (s / np.sum(z ** 2)), "sensitivity fp %.2g c %.2g" % (dfp, dc))


def evaluation_case(name, description, tx, ty, c, kx, ky, xe, ye):
    t = Table("eval_" + name, description +
              "\nbispev and parder (all 0<=nux<kx, 0<=nuy<ky) through dfitpack; "
              "evaluation points include points outside the knot range (clamped)")
    t.int("kx", kx); t.int("ky", ky)
    t.real("tx", tx); t.real("ty", ty); t.real("c", c)
    t.real("x", xe); t.real("y", ye)
    z, ier = dfitpack.bispev(tx, ty, c, kx, ky, xe, ye)
    t.int("ier", ier); t.real("z", z.ravel())
    for nux in range(kx):
        for nuy in range(ky):
            if nux == 0 and nuy == 0:
                continue
            d, ier = dfitpack.parder(tx, ty, c, kx, ky, nux, nuy, xe, ye)
            assert ier == 0
            t.real("d%d%d" % (nux, nuy), d.ravel())
    t.write()


def scattered_data(m, seed, noise, kind="smooth"):
    rng = np.random.default_rng(seed)
    x = rng.random(m)
    y = rng.random(m)
    z = np.sin(5.0 * x + 0.3) * np.cos(4.0 * y) + 0.5 * x * y
    z = z + noise * rng.standard_normal(m)
    return x, y, z


def lwrk2_for(m, kx, ky, nxest, nyest):
    # generous: surfit asks for more (ier > 10) only when this is too small
    u = nxest - kx - 1
    v = nyest - ky - 1
    km = max(kx, ky) + 1
    ne = max(nxest, nyest)
    bx, by = kx * v + ky + 1, ky * u + kx + 1
    b1, b2 = (bx, bx + v - ky) if bx <= by else (by, by + u - kx)
    return u * v * (b2 + 1) + b2


def surfit_case(name, description, x, y, z, w, bbox, kx, ky, s, nxest, nyest, eps=1e-16):
    xb, xe, yb, ye = bbox
    m = len(x)
    lwrk2 = lwrk2_for(m, kx, ky, nxest, nyest)
    nx, tx, ny, ty, c, fp, wrk1, ier = dfitpack.surfit_smth(
        x, y, z, w, xb, xe, yb, ye, kx, ky, s, nxest, nyest, eps, lwrk2)
    t = Table("surfit_" + name, description +
              "\nsurfit iopt=0 through dfitpack.surfit_smth (explicit bbox, nxest, nyest, eps)")
    t.int("iopt", 0)
    t.int("kx", kx); t.int("ky", ky)
    t.real("s", s); t.real("eps", eps); t.real("bbox", [xb, xe, yb, ye])
    t.int("nxest", nxest); t.int("nyest", nyest)
    t.real("x", x); t.real("y", y); t.real("z", z); t.real("w", w)
    t.int("ier", ier); t.real("fp", fp)
    if ier != 10:
        t.real("tx", tx[:nx]); t.real("ty", ty[:ny])
        t.real("c", c[:(nx - kx - 1) * (ny - ky - 1)])
    t.write()
    return ier


def surfit_continue_case(name, description, x, y, z, w, bbox, kx, ky, s_first, s, nxest, nyest):
    """iopt = 1: bisplrep(task=0, s_first) then bisplrep(task=1, s), which hands
    surfit the knots and work array (fp0) of the first call."""
    xb, xe, yb, ye = bbox
    bisplrep(x, y, z, w, xb, xe, yb, ye, kx, ky, task=0, s=s_first, nxest=nxest, nyest=nyest, full_output=1)
    tck, fp, ier, msg = bisplrep(x, y, z, w, xb, xe, yb, ye, kx, ky, task=1, s=s, nxest=nxest, nyest=nyest,
                                 full_output=1)
    t = Table("surfit_" + name, description +
              "\nsurfit iopt=0 with s_first, then iopt=1 with s, through bisplrep(task=0), bisplrep(task=1)")
    t.int("iopt", 1)
    t.int("kx", kx); t.int("ky", ky)
    t.real("s_first", s_first)
    t.real("s", s); t.real("eps", 1e-16); t.real("bbox", [xb, xe, yb, ye])
    t.int("nxest", nxest); t.int("nyest", nyest)
    t.real("x", x); t.real("y", y); t.real("z", z); t.real("w", w)
    t.int("ier", ier); t.real("fp", fp)
    t.real("tx", tck[0]); t.real("ty", tck[1])
    t.real("c", tck[2][:(len(tck[0]) - kx - 1) * (len(tck[1]) - ky - 1)])
    t.write()


def surfit_lsq_case(name, description, x, y, z, w, bbox, kx, ky, txi, tyi, eps=1e-16):
    xb, xe, yb, ye = bbox
    tx = np.concatenate([[xb] * (kx + 1), txi, [xe] * (kx + 1)])
    ty = np.concatenate([[yb] * (ky + 1), tyi, [ye] * (ky + 1)])
    nx, ny = len(tx), len(ty)
    nmax = max(nx, ny)
    txp = np.zeros(nmax); txp[:nx] = tx
    typ = np.zeros(nmax); typ[:ny] = ty
    lwrk2 = lwrk2_for(len(x), kx, ky, nx, ny)
    tx2, ty2, c, fp, ier = dfitpack.surfit_lsq(x, y, z, nx, txp, ny, typ, w, xb, xe, yb, ye,
                                               kx, ky, eps, lwrk2)
    t = Table("surfit_" + name, description +
              "\nsurfit iopt=-1 through dfitpack.surfit_lsq (nxest=nx, nyest=ny)")
    t.int("iopt", -1)
    t.int("kx", kx); t.int("ky", ky)
    t.real("s", 0.0); t.real("eps", eps); t.real("bbox", [xb, xe, yb, ye])
    t.int("nxest", nx); t.int("nyest", ny)
    t.real("x", x); t.real("y", y); t.real("z", z); t.real("w", w)
    t.int("ier", ier); t.real("fp", fp)
    t.real("tx", tx2[:nx]); t.real("ty", ty2[:ny])
    t.real("c", c[:(nx - kx - 1) * (ny - ky - 1)])
    t.write()
    return ier


def main():
    os.makedirs(OUT, exist_ok=True)
    # ---- regrid -----------------------------------------------------------
    tx, ty, c = regrid_case("interp_k33", "grid 9 x 7, exact data, s = 0 (interpolation)",
                            9, 7, 3, 3, 0.0, 1, 0.0, uneven=True)
    regrid_case("interp_k24", "grid 8 x 9, exact data, s = 0, even and odd degrees",
                8, 9, 2, 4, 0.0, 2, 0.0, uneven=True)
    regrid_case("smooth_k33", "grid 21 x 17, noisy data, bicubic, s = 0.05",
                21, 17, 3, 3, 0.05, 3, 0.02)
    regrid_case("smooth_k15", "grid 15 x 19, noisy data, kx=1, ky=5, s = 0.02",
                15, 19, 1, 5, 0.02, 4, 0.01, uneven=True)
    regrid_case("smooth_k42_bbox", "grid 18 x 16, noisy data, kx=4, ky=2, s = 0.01, bbox wider than the data",
                18, 16, 4, 2, 0.01, 5, 0.01, bbox_data=(0.1, 0.9, 0.2, 1.0), bbox=(0.0, 1.0, 0.0, 1.2))
    regrid_case("poly", "grid 10 x 10, s large: least-squares polynomial (ier = -2)",
                10, 10, 3, 3, 100.0, 6, 0.01)
    regrid_case("invalid_bbox", "xb > x(1): ier = 10", 10, 10, 3, 3, 0.1, 6, 0.01,
                bbox=(0.05, 1.0, 0.0, 1.0))
    regrid_case("invalid_order", "x not strictly increasing (x(4) = x(3)): ier = 10", 10, 10, 3, 3, 0.1, 6, 0.01,
                duplicate=True)
    # p-iteration failures, replayed from the search (see regrid_search_draw)
    # (only cases the genuine FITPACK reproduces to 1e-11 when z is perturbed at
    # 1e-15: most ier = 3 and all ier = 2 cases found are rounding-chaotic, fp
    # changing by 1e-8 up to 6000 % or ier changing under such perturbations;
    # regrid_search prints it. Hence no ier = 2 case for regrid: seeds 2, 5, 6, 7
    # found six, none stable - ier itself changes under the perturbation or fp
    # moves by 3800 %.)
    for name, seed, trial, ier in [("maxit_a", 1, 1263, 3), ("maxit_b", 1, 1835, 3), ("maxit_c", 1, 1963, 3)]:
        x, y, z, kx, ky, s = regrid_replay(seed, -14.0, trial)
        regrid_data_case(name, "random %d x %d grid (search seed %d, trial %d), kx=%d, ky=%d, s = %.3g: ier = %d"
                         % (len(x), len(y), seed, trial, kx, ky, s, ier),
                         x, y, z, (x[0], x[-1], y[0], y[-1]), kx, ky, s, ier_expected=ier)
    # ier = 1 (nxest, nyest too small) cannot be reached: regrid_smth and
    # RectBivariateSpline fix nxest = mx+kx+1, nyest = my+ky+1, with which the
    # knots reach interpolation (ier = -1) before storage runs out; the test
    # checks ier = 1 by what must hold instead.
    # ---- bispev / parder ----------------------------------------------------
    xe = np.array([-0.1, 0.0, 0.13, 0.5, 0.5, 0.77, 1.0, 1.2])
    ye = np.array([-0.2, 0.0, 0.31, 0.66, 0.9, 1.0, 1.1])
    tx, ty, c = regrid_case("interp_k55", "grid 10 x 11, exact data, s = 0, degree 5 (for parder to third order)",
                            10, 11, 5, 5, 0.0, 7, 0.0, uneven=True)
    evaluation_case("k55", "the quintic interpolant of regrid_interp_k55", tx, ty, c, 5, 5, xe, ye)
    tx, ty, c = regrid_case("smooth_k32", "grid 20 x 20, noisy, kx=3, ky=2, s = 0.03",
                            20, 20, 3, 2, 0.03, 8, 0.01)
    evaluation_case("k32", "the spline of regrid_smooth_k32", tx, ty, c, 3, 2, xe, ye)
    # ---- surfit -----------------------------------------------------------
    bbox = (0.0, 1.0, 0.0, 1.0)
    x, y, z = scattered_data(80, 11, 0.01)
    w = np.ones_like(x)
    surfit_case("smooth_k33", "80 scattered noisy points, bicubic, s = 0.01", x, y, z, w, bbox, 3, 3, 0.01, 12, 12)
    surfit_case("smooth_k33_s2", "same data, bicubic, s = 0.05", x, y, z, w, bbox, 3, 3, 0.05, 12, 12)
    surfit_case("smooth_k12", "same data, kx=1, ky=2, s = 0.004", x, y, z, w, bbox, 1, 2, 0.004, 14, 14)
    surfit_case("smooth_k53", "same data, kx=5, ky=3, s = 0.005", x, y, z, w, bbox, 5, 3, 0.005, 14, 12)
    rng = np.random.default_rng(12)
    wv = 0.5 + rng.random(len(x)) * 2.0
    surfit_case("weights_k33", "same data with weights in [0.5, 2.5], bicubic, s = 0.05",
                x, y, z, wv, bbox, 3, 3, 0.05, 12, 12)
    surfit_continue_case("continue", "same data, bicubic: s = 0.05 from scratch, then continued (iopt = 1) "
                         "to s = 0.005", x, y, z, w, bbox, 3, 3, 0.05, 0.005, 14, 14)
    surfit_case("poly", "same data, s large: least-squares polynomial (ier = -2)",
                x, y, z, w, bbox, 3, 3, 10.0, 12, 12)
    surfit_case("small_s", "same data, s = 1e-5 (nearly interpolating: knots run out, ier = 1 or 4/5)",
                x, y, z, w, bbox, 3, 3, 1e-5, 9, 9)
    x2, y2, z2 = scattered_data(200, 13, 0.02)
    surfit_case("smooth_k22_200", "200 scattered points, biquadratic, s = 0.1, bbox wider than data",
                x2, y2, z2, np.ones_like(x2), (-0.1, 1.1, -0.2, 1.0 + 1e-9 + y2.max() - y2.max()), 2, 2, 0.1, 15, 15)
    # nearly collinear: points close to the line y = 0.3 + 0.4 x
    rng = np.random.default_rng(21)
    xc = np.sort(rng.random(40))
    yc = 0.3 + 0.4 * xc + 1e-3 * rng.standard_normal(40)
    zc = np.sin(9.0 * xc) + 0.1 * yc
    txi = np.array([0.3, 0.6]); tyi = np.array([0.25, 0.5, 0.75])
    surfit_lsq_case("collinear_lsq", "40 points near the line y = 0.3 + 0.4 x, given knots: rank-deficient (ier < -2), minimum-norm solution",
                    xc, yc, zc, np.ones_like(xc), bbox, 3, 3, txi, tyi)
    surfit_case("collinear_smooth", "40 points near the line y = 0.3 + 0.4 x, s = 1e-4: knots added until rank-deficient",
                xc, yc, zc, np.ones_like(xc), bbox, 3, 3, 1e-4, 11, 11)
    surfit_lsq_case("lsq_k33", "80 scattered points, given interior knots, bicubic (iopt = -1)",
                    x, y, z, w, bbox, 3, 3, np.array([0.35, 0.7]), np.array([0.5]))
    surfit_lsq_case("lsq_k24_w", "80 scattered points, given knots, kx=2, ky=4, weights",
                    x, y, z, wv, bbox, 2, 4, np.array([0.25, 0.5, 0.75]), np.array([0.4]))
    surfit_case("invalid_bbox", "a point outside the bbox: ier = 10", x, y, z, w, (0.0, 0.9, 0.0, 1.0), 3, 3, 0.05, 12, 12)
    w0 = w.copy(); w0[5] = 0.0
    surfit_case("invalid_weight", "a zero weight: ier = 10", x, y, z, w0, bbox, 3, 3, 0.05, 12, 12)
    surfit_case("interp_nest_small", "s = 0 with nxest = nyest = 12: knots run out (ier = 1)",
                x, y, z, w, bbox, 3, 3, 0.0, 12, 12)
    surfit_case("interp_rank", "s = 0 with nxest = nyest = 20: more coefficients than data, minimum-norm "
                "interpolant (ier = -rank)", x, y, z, w, bbox, 3, 3, 0.0, 20, 20)
    surfit_lsq_case("collinear_lsq_k22", "40 points near the line y = 0.3 + 0.4 x, given knots, biquadratic: "
                    "rank-deficient (ier < -2)", xc, yc, zc, np.ones_like(xc), bbox, 2, 2,
                    np.array([0.2, 0.4, 0.6, 0.8]), np.array([0.3, 0.5, 0.7]))
    # more knots in y than in x: surfit swaps x and y to narrow the band
    rng = np.random.default_rng(5)
    xs = rng.random(60)
    ys = rng.random(60)
    zs = np.sin(2 * xs) + np.sin(9 * ys) + 0.01 * rng.standard_normal(60)
    surfit_case("swap_k33", "60 points varying faster in y: knots mostly in y, x and y swapped internally, s = 0.003",
                xs, ys, zs, np.ones(60), bbox, 3, 3, 0.003, 12, 14)
    # clustered data: the smoothing spline itself is rank deficient
    rng = np.random.default_rng(9)
    xq = np.r_[rng.random(30) * 0.02, rng.random(10)]
    yq = rng.random(40)
    zq = np.sin(40 * xq) + yq
    surfit_case("cluster_rank", "30 of 40 points in x < 0.02, s = 1e-5: rank-deficient smoothing spline (ier < -2)",
                xq, yq, zq, np.ones(40), bbox, 3, 3, 1e-5, 15, 15)
    # s = 0, bilinear, 18 noisy points: knots added until more coefficients than data (ier = 4)
    rng = np.random.default_rng(0)
    x4 = rng.random(18)
    y4 = rng.random(18)
    z4 = np.sin(5 * x4) * np.cos(4 * y4) + 0.1 * rng.standard_normal(18)
    surfit_case("more_coef_than_data", "18 noisy points, kx = ky = 1, s = 0: ier = 4",
                x4, y4, z4, np.ones(18), bbox, 1, 1, 0.0, 16, 16)
    # 34 of 40 points in x < 0.01: new knots would split intervals worse than 10:1 (ier = 5),
    # with more knot storage the p-iteration leaves its theory (ier = 2)
    rng = np.random.default_rng(0)
    x5 = np.r_[rng.random(34) * 0.01, rng.random(6)]
    y5 = rng.random(40)
    z5 = np.sin(30 * x5) + np.cos(20 * y5) + 0.01 * rng.standard_normal(40)
    surfit_case("no_more_knots", "34 of 40 points in x < 0.01, s = 0.01, nxest = nyest = 12: ier = 5",
                x5, y5, z5, np.ones(40), bbox, 3, 3, 0.01, 12, 12)
    surfit_case("s_too_small", "the same data, nxest = nyest = 20: ier = 2",
                x5, y5, z5, np.ones(40), bbox, 3, 3, 0.01, 20, 20)
    # thesis 3.5.3.3: paraboloids (3.58), 13 x 13 points, degree 5, s = 0.05
    for i, (a2, h) in enumerate([(3.0, 2.0), (0.5, 0.5)]):
        u = np.linspace(-h, h, 13)
        U, V = np.meshgrid(u, u, indexing="ij")
        zp = (U ** 2 + V ** 2) / a2
        surfit_case("thesis_paraboloid%d" % (i + 1),
                    "thesis 3.5.3.3: paraboloid (3.58) c = 1, a^2 = b^2 = %g on [-%g, %g]^2, 13 x 13 points, "
                    "kx = ky = 5, s = 0.05" % (a2, h, h),
                    U.ravel(), V.ravel(), zp.ravel(), np.ones(169), (-h, h, -h, h), 5, 5, 0.05, 20, 20)


if __name__ == "__main__":
    if "--search-regrid" in sys.argv:
        regrid_search(seeds=[int(a) for a in sys.argv[2:]] or range(1, 6))
    else:
        main()
        write_files()
