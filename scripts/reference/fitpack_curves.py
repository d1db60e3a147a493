#!/usr/bin/python3
"""Reference tables for slidesim's FITPACK curve routines, from the genuine
Fortran FITPACK inside Debian's python3-scipy (1.10.1, double precision).

Run from the repository root with Debian's interpreter:
    /usr/bin/python3 scripts/reference/fitpack_curves.py
It writes tests/reference/fitpack/curves_*.txt. Table format (read by
external/fitpack/tests/support/fitpack_reference_io.f90):
    '#' lines are comments; 'case <name>' ... 'end' is one case; inside,
    '<key> <count>' is followed by <count> numbers (integers written as numbers).
Inputs and outputs use the names of the FITPACK calling sequences; the knots t
and coefficients c are the first n (resp. nc) entries the routine returns.
"""
import os
import sys

import numpy as np
import scipy
from scipy.interpolate import dfitpack, splrep, splprep, splev, insert, splint, sproot, spalde
from scipy.interpolate import _fitpack
dfitpack_int = dfitpack.types.intvar.dtype

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tests', 'reference', 'fitpack')


class Table:
    def __init__(self, name, description):
        self.name = name
        self.lines = [
            '# slidesim FITPACK reference table: ' + name,
            '# made by scripts/reference/fitpack_curves.py with scipy %s (numpy %s, python %s)'
            % (scipy.__version__, np.__version__, sys.version.split()[0]),
            '# genuine Fortran FITPACK in double precision (Debian python3-scipy).',
        ] + ['# ' + line for line in description.strip().splitlines()] + [
            '# format: "case <name>" ... "end"; inside, "<key> <count>" then <count> numbers.',
        ]
        self.count = 0

    def case(self, name, **entries):
        self.lines.append('case ' + name)
        for key, value in entries.items():
            v = np.atleast_1d(np.asarray(value, dtype=float)).ravel()
            self.lines.append('%s %d' % (key, v.size))
            for i in range(0, v.size, 4):
                self.lines.append(' '.join('%.17e' % e for e in v[i:i + 4]))
        self.lines.append('end')
        self.count += 1

    def write(self):
        os.makedirs(OUT, exist_ok=True)
        with open(os.path.join(OUT, self.name), 'w') as f:
            f.write('\n'.join(self.lines) + '\n')
        print('%s: %d cases' % (self.name, self.count))


rng = np.random.RandomState(20261121)


def data_1d(m, noisy, nonuniform=True):
    if nonuniform:
        x = np.sort(rng.uniform(0.0, 4.0, m))
        x[0], x[-1] = 0.0, 4.0
    else:
        x = np.linspace(0.0, 4.0, m)
    y = np.sin(1.3 * x) + 0.3 * x**2 - 0.1 * x**3
    if noisy:
        y = y + rng.normal(0.0, 0.05, m)
    return x, y


# ---------------------------------------------------------------- curfit
def curfit_call(iopt, x, y, w, k, s, nest, xb=None, xe=None, lwrk=None, state=None):
    m = len(x)
    if lwrk is None:
        lwrk = m * (k + 1) + nest * (7 + 3 * k)
    if state is None:
        t = np.zeros(nest)
        wrk = np.zeros(lwrk)
        iwrk = np.zeros(nest, dtype=np.int32)
    else:
        t, wrk, iwrk = state
    xb = x[0] if xb is None else xb
    xe = x[-1] if xe is None else xe
    n, c, fp, ier = dfitpack.curfit(iopt, x, y, w, t, wrk, iwrk, xb=xb, xe=xe, k=k, s=s)
    return n, t.copy(), c.copy(), fp, ier, (t, wrk, iwrk), lwrk, xb, xe


def curfit_case(tab, name, iopt, x, y, w, k, s, nest, xb=None, xe=None, lwrk=None):
    n, t, c, fp, ier, state, lwrk, xb, xe = curfit_call(iopt, x, y, w, k, s, nest, xb, xe, lwrk)
    nk1 = max(n - k - 1, 0)
    out = dict(iopt=iopt, k=k, s=s, nest=nest, lwrk=lwrk, xb=xb, xe=xe, x=x, y=y, w=w,
               ier=ier, n=n, fp=fp, t=t[:n], c=c[:nk1])
    tab.case(name, **out)
    return ier, state


def curfit_tables():
    tab = Table('curves_curfit.txt', """
curfit cases. Call: curfit(iopt,m,x,y,w,xb,xe,k,s,nest,n,t,c,fp,wrk,lwrk,iwrk,ier)
through scipy.interpolate.dfitpack.curfit (iopt 0 and 1, the netlib wrapper with its
input checks), and splrep(t=interior knots) for iopt=-1 (given knots t_in, n_in).
Continuation cases (iopt=1) first call iopt=0 with s_first on the same workspace.
Outputs: ier, n, fp, t(1:n), c(1:n-k-1).""")
    for k in range(1, 6):
        # interpolation of exact data
        x, y = data_1d(14 + k, noisy=False)
        w = np.ones_like(x)
        curfit_case(tab, 'interp_k%d' % k, 0, x, y, w, k, 0.0, len(x) + k + 1)
        # smoothing of noisy data, several s, with and without weights
        x, y = data_1d(45, noisy=True)
        w = np.ones_like(x)
        wv = 1.0 / rng.uniform(0.03, 0.08, len(x))
        for j, s in enumerate([0.5, 0.08, 0.02, 0.004]):
            curfit_case(tab, 'smooth_k%d_s%d' % (k, j), 0, x, y, w, k, s, len(x) + k + 1)
        for j, s in enumerate([60.0, 40.0, 20.0]):
            curfit_case(tab, 'weighted_k%d_s%d' % (k, j), 0, x, y, wv, k, s, len(x) + k + 1)
        # polynomial is good enough (ier = -2)
        curfit_case(tab, 'poly_k%d' % k, 0, x, y, w, k, 50.0, len(x) + k + 1)
        # nest too small (ier = 1)
        curfit_case(tab, 'nest_small_k%d' % k, 0, x, y, w, k, 0.001, 2 * k + 5)
        # continuation iopt = 1 from a larger s, and back to a larger s
        # (dfitpack.fpcurf0 / fpcurf1 call fpcurf with iopt 0 and 1 on kept work arrays,
        # as UnivariateSpline.set_smoothing_factor; the curfit wrapper's iopt=1 restarts)
        for j, (s1, s2) in enumerate([(0.1, 0.03), (0.03, 0.2), (0.05, 0.0)]):
            nest = len(x) + k + 1
            data = dfitpack.fpcurf0(x, y, k, w=w, xb=x[0], xe=x[-1], s=s1, nest=nest)
            data = dfitpack.fpcurf1(*(data[:6] + (s2,) + data[7:]))
            n, t, c, fp, ier = data[7], data[8], data[9], data[10], data[13]
            lwrk = len(x) * (k + 1) + nest * (7 + 3 * k)
            tab.case('continue_k%d_%d' % (k, j), iopt=1, k=k, s_first=s1, s=s2, nest=nest, lwrk=lwrk,
                     xb=x[0], xe=x[-1], x=x, y=y, w=w, ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - k - 1])
        # given knots (iopt = -1), weighted, bounding box wider than the data
        interior = np.array([0.4, 1.1, 1.7, 2.2, 3.05, 3.5])
        xb, xe = -0.25, 4.5
        tck, fp, ier, msg = splrep(x, y, wv, xb=xb, xe=xe, k=k, t=interior, full_output=1)
        t, c, _ = tck
        n = len(t)
        tab.case('given_k%d' % k, iopt=-1, k=k, s=0.0, nest=n, xb=xb, xe=xe, x=x, y=y, w=wv,
                 n_in=n, t_in=t, ier=ier, n=n, fp=fp, t=t, c=c[:n - k - 1])
    # exact data, uniform, smoothing with s > 0 on a cubic
    x, y = data_1d(30, noisy=False, nonuniform=False)
    curfit_case(tab, 'exact_smooth_k3', 0, x, y, np.ones_like(x), 3, 1e-4, 34)
    # invalid inputs: ier = 10
    x, y = data_1d(20, noisy=True)
    w = np.ones_like(x)
    nest = 30
    lw = 20 * 4 + nest * 16
    bad = [
        ('bad_iopt', dict(iopt=2)),
        ('bad_lwrk', dict(lwrk=lw - 1)),
        ('bad_xb', dict(xb=x[0] + 0.01)),
        ('bad_xe', dict(xe=x[-1] - 0.01)),
        ('bad_s_negative', dict(s=-1.0)),
        ('bad_nest_interp', dict(s=0.0, nest=20 + 3)),
        ('bad_nest_min', dict(nest=7)),
    ]
    for name, change in bad:
        a = dict(iopt=0, k=3, s=0.1, nest=nest, lwrk=None, xb=None, xe=None)
        a.update(change)
        if a['lwrk'] is None:
            a['lwrk'] = 20 * 4 + a['nest'] * 16
        try:
            n, t, c, fp, ier, state, lwrk, xb, xe = curfit_call(a['iopt'], x, y, w, a['k'], a['s'], a['nest'],
                                                                a['xb'], a['xe'], a['lwrk'])
        except Exception as e:  # the f2py wrapper refuses some inputs before FITPACK sees them
            print('skipped', name, e)
            continue
        assert ier == 10, (name, ier)
        tab.case(name, iopt=a['iopt'], k=a['k'], s=a['s'], nest=a['nest'], lwrk=lwrk, xb=xb, xe=xe,
                 x=x, y=y, w=w, ier=ier)
    # given knots violating Schoenberg-Whitney (five knots in one data gap)
    gap = 0.5 * (x[5] + x[6])
    tin = np.r_[[x[0]] * 4, gap + (x[6] - x[5]) * np.array([-0.2, -0.1, 0.0, 0.1, 0.2]), [x[-1]] * 4]
    tab.case('bad_given_knots', iopt=-1, k=3, s=0.0, nest=len(tin), lwrk=20 * 4 + len(tin) * 16,
             xb=x[0], xe=x[-1], x=x, y=y, w=w, n_in=len(tin), t_in=tin, ier=10)
    _check_bad_given(x, y, w, tin)
    # the p-iteration gives up (ier = 2: f(p) out of order; ier = 3: maxit) on random
    # small data sets with badly scaled s; searched with a separate generator
    search = np.random.RandomState(5)
    found = {}
    for trial in range(60000):
        m = int(search.randint(8, 40))
        kk = int(search.randint(1, 6))
        xx = np.sort(search.uniform(0, 1, m))
        if np.any(np.diff(xx) <= 1e-3):
            continue
        yy = search.normal(0, 1, m) * 10**search.uniform(-3, 3)
        if search.rand() < 0.5:
            yy = np.round(yy, 0)
        s = 10.0**search.uniform(-16, 1) * np.sum(yy**2)
        nest = m + kk + 1
        n, t, c, fp, ier, state, lwrk, xb, xe = curfit_call(0, xx, yy, np.ones(m), kk, s, nest)
        if ier in (2, 3) and ier not in found:
            # only cases the genuine curfit reproduces to 1e-11 when y is perturbed
            # at 1e-15 (the ier = 2 case this table held before moved our fp by
            # 1.4e-3 when compiled with -march=x86-64-v3 -ffp-contract=fast:
            # rounding-chaotic, no reference). Even the stable ier = 2 case now
            # chosen moves one coefficient of ours by 1.5e-7 under that FMA build;
            # the default x86-64-v2 build matches to 1e-8.
            pert = np.random.RandomState(99)
            stable = True
            for _ in range(8):
                out = curfit_call(0, xx, yy * (1 + 1e-15 * pert.uniform(-1, 1, m)), np.ones(m), kk, s, nest)
                if out[4] != ier or out[0] != n or not abs(out[3] - fp) <= 1e-11 * abs(fp):
                    stable = False
                    break
            if not stable:
                continue
            found[ier] = True
            tab.case('provoked_ier%d' % ier, iopt=0, k=kk, s=s, nest=nest, lwrk=lwrk, xb=xb, xe=xe,
                     x=xx, y=yy, w=np.ones(m), ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - kk - 1])
        if len(found) == 2:
            break
    assert len(found) == 2, found
    # iopt = -1 without interior knots: the least-squares polynomial (ier = -2)
    x, y = data_1d(20, noisy=True)
    w = np.ones_like(x)
    tck, fp, ier, msg = splrep(x, y, w, k=3, t=[], full_output=1)
    t, c, _ = tck
    tab.case('given_no_interior', iopt=-1, k=3, s=0.0, nest=8, xb=x[0], xe=x[-1], x=x, y=y, w=w,
             n_in=8, t_in=t, ier=ier, n=8, fp=fp, t=t, c=c[:4])
    tab.write()


def _check_bad_given(x, y, w, tin):
    try:
        tck, fp, ier, msg = splrep(x, y, w, k=3, t=tin[4:-4], full_output=1)
    except Exception:
        return
    assert ier == 10, ier


# ---------------------------------------------------------------- provoked ier 2 / 3
# percur, parcur and clocur give up in their p-iteration (ier = 3: maxit = 20
# reached; ier = 2: f(p) out of the order theory promises) only for particular
# data and s. The cases were found by a random search over small data sets
# (`fitpack_curves.py --search <percur|parcur|clocur> <seed> [lo]` prints trial and
# ier); search_draw replays trial `trial` of a seed without calling FITPACK for
# the earlier ones. ipar = 1 (the given u), unit weights, nest = m+k+1 (parcur)
# or m+2k (percur, clocur): enough for interpolation.
def search_draw(search, lo, closed):
    m = int(search.randint(8, 40))
    k = int(search.randint(1, 6))
    idim = int(search.randint(1, 4))
    u = np.sort(search.uniform(0, 1, m))
    y = search.normal(0, 1, (idim, m)) * 10 ** search.uniform(-3, 3)
    rounded = search.rand() < 0.5
    srel = 10.0 ** search.uniform(lo, 0)
    usable = bool(np.all(np.diff(u) > 1e-3))
    if rounded:
        y = np.round(y, 0)
    if closed:
        y[:, -1] = y[:, 0]
    return usable, u, y, k, srel * np.sum(y ** 2)


def search_replay(kind, seed, lo, trial):
    search = np.random.RandomState(seed)
    for _ in range(trial + 1):
        draw = search_draw(search, lo, kind != 'parcur')
    assert draw[0]
    return draw[1:]


def search_fit(kind, u, y, k, s):
    m = len(u)
    if kind == 'percur':
        n, t, c, fp, ier = percur_call(0, u, y[0], np.ones(m), k, s, m + 2 * k)[:5]
    else:
        n, t, c, fp, ier = parcur_call(0, 1, u, y, np.ones(m), u[0], u[-1], k, s,
                                       m + k + 1 if kind == 'parcur' else m + 2 * k, per=int(kind == 'clocur'))[:5]
    return n, c, fp, ier


def sensitivity(kind, u, y, k, s, samples=8):
    """Largest relative change of fp (and of the coefficients) when the data are
    perturbed at 1e-15 relative: a case the genuine FITPACK itself cannot reproduce
    to 1e-8 under such perturbations is rounding-chaotic and unfit as a reference."""
    n0, c0, fp0, ier0 = search_fit(kind, u, y, k, s)
    pert = np.random.RandomState(99)
    dfp = dc = 0.0
    for _ in range(samples):
        yp = y * (1 + 1e-15 * pert.uniform(-1, 1, y.shape))
        if kind != 'parcur':
            yp[:, -1] = yp[:, 0]
        n, c, fp, ier = search_fit(kind, u, yp, k, s)
        if ier != ier0 or n != n0:
            return np.inf, np.inf
        dfp = max(dfp, abs(fp - fp0) / abs(fp0))
        big = np.abs(c0) > 1e-8 * np.max(np.abs(c0))
        if np.any(big):
            dc = max(dc, np.max(np.abs(c - c0)[big] / np.abs(c0[big])))
    return dfp, dc


def search_run(kind, seed, lo=-16.0, trials=3000):
    search = np.random.RandomState(seed)
    for trial in range(trials):
        usable, u, y, k, s = search_draw(search, lo, kind != 'parcur')
        if not usable:
            continue
        ier = search_fit(kind, u, y, k, s)[3]
        if ier in (1, 2, 3):
            dfp, dc = sensitivity(kind, u, y, k, s)
            print(kind, 'seed', seed, 'trial', trial, 'ier', ier, 'm', len(u), 'k', k, 'idim', y.shape[0],
                  's/sum y^2 %.3g' % (s / np.sum(y ** 2)), 'sensitivity fp %.2g c %.2g' % (dfp, dc))


def parcur_call(iopt, ipar, u, x, w, ub, ue, k, s, nest, state=None, per=0):
    """parcur (per=0) or clocur (per=1) through scipy's _fitpack._parcur, the C glue
    splprep uses; coefficients repacked to the FITPACK layout c(n*(j-1)+i)."""
    idim, m = x.shape
    if per:
        lwrk = m * (k + 1) + nest * (7 + idim + 5 * k)
    else:
        lwrk = m * (k + 1) + nest * (6 + idim + 3 * k)
    if state is None:
        t = np.zeros(0)
        wrk = np.zeros(0)
        iwrk = np.zeros(0, dtype=dfitpack_int)
    else:
        t, wrk, iwrk = state
    uu = u.copy()
    t, c, o = _fitpack._parcur(x.T.ravel().copy(), w, uu, ub, ue, k, iopt, ipar, s, t, nest, wrk, iwrk, per)
    n = len(t)
    nk1 = n - k - 1
    cc = np.zeros(nest * idim)
    for j in range(idim):
        cc[n * j:n * j + nk1] = c[nk1 * j:nk1 * (j + 1)]
    return n, t.copy(), cc, o['fp'], o['ier'], o['u'], lwrk, (t, o['wrk'], o['iwrk'])


# ---------------------------------------------------------------- percur
def percur_call(iopt, x, y, w, k, s, nest, lwrk=None, state=None):
    m = len(x)
    if lwrk is None:
        lwrk = m * (k + 1) + nest * (8 + 5 * k)
    if state is None:
        t = np.zeros(nest)
        wrk = np.zeros(lwrk)
        iwrk = np.zeros(nest, dtype=np.int32)
    else:
        t, wrk, iwrk = state
    n, c, fp, ier = dfitpack.percur(iopt, x, y, w, t, wrk, iwrk, k=k, s=s)
    return n, t.copy(), c.copy(), fp, ier, (t, wrk, iwrk), lwrk


def periodic_data(m, noisy):
    x = np.sort(rng.uniform(0.0, 2 * np.pi, m))
    x[0], x[-1] = 0.0, 2 * np.pi
    y = np.sin(x) + 0.4 * np.cos(2 * x) + 0.2 * np.sin(3 * x)
    if noisy:
        y = y + rng.normal(0.0, 0.05, m)
    y[-1] = y[0]
    return x, y


def percur_tables():
    tab = Table('curves_percur.txt', """
percur cases. Call: percur(iopt,m,x,y,w,k,s,nest,n,t,c,fp,wrk,lwrk,iwrk,ier) through
scipy.interpolate.dfitpack.percur (netlib wrapper with its checks); iopt=-1 through
splrep(per=1, t=interior knots). Period x(m)-x(1); y(m) = y(1). Outputs: ier, n, fp, t(1:n), c(1:n-k-1).""")
    for k in range(1, 6):
        x, y = periodic_data(16 + k, noisy=False)
        w = np.ones_like(x)
        nest = len(x) + 2 * k
        n, t, c, fp, ier, state, lwrk = percur_call(0, x, y, w, k, 0.0, nest)
        tab.case('interp_k%d' % k, iopt=0, k=k, s=0.0, nest=nest, lwrk=lwrk, x=x, y=y, w=w,
                 ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - k - 1])
        x, y = periodic_data(50, noisy=True)
        w = np.ones_like(x)
        wv = 1.0 / rng.uniform(0.03, 0.08, len(x))
        nest = len(x) + 2 * k
        for j, s in enumerate([0.6, 0.1, 0.03]):
            n, t, c, fp, ier, state, lwrk = percur_call(0, x, y, w, k, s, nest)
            tab.case('smooth_k%d_s%d' % (k, j), iopt=0, k=k, s=s, nest=nest, lwrk=lwrk, x=x, y=y, w=w,
                     ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - k - 1])
        for j, s in enumerate([60.0, 35.0]):
            n, t, c, fp, ier, state, lwrk = percur_call(0, x, y, wv, k, s, nest)
            tab.case('weighted_k%d_s%d' % (k, j), iopt=0, k=k, s=s, nest=nest, lwrk=lwrk, x=x, y=y, w=wv,
                     ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - k - 1])
        n, t, c, fp, ier, state, lwrk = percur_call(0, x, y, w, k, 100.0, nest)
        tab.case('constant_k%d' % k, iopt=0, k=k, s=100.0, nest=nest, lwrk=lwrk, x=x, y=y, w=w,
                 ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - k - 1])
        n, t, c, fp, ier, state, lwrk = percur_call(0, x, y, w, k, 0.001, 2 * k + 6)
        tab.case('nest_small_k%d' % k, iopt=0, k=k, s=0.001, nest=2 * k + 6, lwrk=lwrk, x=x, y=y, w=w,
                 ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - k - 1])
        # no iopt=1 case: dfitpack.percur hides n, so its iopt=1 does not continue
        interior = np.array([0.7, 1.5, 2.6, 3.3, 4.4, 5.1])
        tck, fp, ier, msg = splrep(x, y, wv, k=k, t=interior, per=1, full_output=1)
        t, c, _ = tck
        n = len(t)
        tab.case('given_k%d' % k, iopt=-1, k=k, s=0.0, nest=n, x=x, y=y, w=wv, n_in=n, t_in=t,
                 ier=ier, n=n, fp=fp, t=t, c=c[:n - k - 1])
    x, y = periodic_data(20, noisy=True)
    w = np.ones_like(x)
    for name, iopt, k, s, nest in [('bad_k', 0, 6, 0.1, 40), ('bad_s_negative', 0, 3, -1.0, 40),
                                   ('bad_nest_interp', 0, 3, 0.0, 20 + 5), ('bad_iopt', 3, 3, 0.1, 40)]:
        try:
            n, t, c, fp, ier, state, lwrk = percur_call(iopt, x, y, w, k, s, nest)
        except Exception as e:
            print('skipped', name, e)
            continue
        assert ier == 10, (name, ier)
        tab.case(name, iopt=iopt, k=k, s=s, nest=nest, lwrk=lwrk, x=x, y=y, w=w, ier=ier)
    # the p-iteration gives up (see search_draw)
    for name, seed, lo, trial, ier_wanted in PROVOKED['percur']:
        x, y, k, s = search_replay('percur', seed, lo, trial)
        y = y[0]
        w = np.ones_like(x)
        nest = len(x) + 2 * k
        n, t, c, fp, ier, state, lwrk = percur_call(0, x, y, w, k, s, nest)
        assert ier == ier_wanted, (name, ier, ier_wanted)
        tab.case(name, iopt=0, k=k, s=s, nest=nest, lwrk=lwrk, x=x, y=y, w=w,
                 ier=ier, n=n, fp=fp, t=t[:n], c=c[:n - k - 1])
    # The only ier = 2 the search found that is not rounding-chaotic (seed 17,
    # trial 678 at lo = -16) is no reference: all of fp sits in intervals without
    # data, the original fpknot then finds no interval to split and writes outside
    # its arrays, and the knot vector percur returns is corrupt (t(17) = 0 between
    # 0.96 and 0.99). The case is kept with genuine_corrupt = 1 and the genuine
    # ier and knots for the record; the test checks it by what must hold.
    x, y, k, s = search_replay('percur', 17, -16.0, 678)
    y = y[0]
    w = np.ones_like(x)
    nest = len(x) + 2 * k
    n, t, c, fp, ier, state, lwrk = percur_call(0, x, y, w, k, s, nest)
    assert ier == 2 and np.any(np.diff(t[:n]) < 0), (ier, t[:n])
    tab.case('fpknot_no_interval', iopt=0, k=k, s=s, nest=nest, lwrk=lwrk, x=x, y=y, w=w,
             genuine_corrupt=1, ier_genuine=ier, t_genuine=t[:n])
    tab.write()


# ---------------------------------------------------------------- parcur / clocur
def space_curve(m, idim, noisy, closed=False):
    if closed:
        u = np.sort(rng.uniform(0, 2 * np.pi, m))
        u[0], u[-1] = 0.0, 2 * np.pi
        pts = [np.cos(u) * (1 + 0.3 * np.cos(3 * u)), np.sin(u) * (1 + 0.3 * np.cos(3 * u)), 0.4 * np.sin(2 * u)]
    else:
        u = np.sort(rng.uniform(0, 3, m))
        u[0], u[-1] = 0.0, 3.0
        pts = [np.cos(1.7 * u) * (1 + u), np.sin(1.7 * u) * (1 + u), 0.5 * u + 0.2 * np.sin(4 * u)]
    x = np.array(pts[:idim])
    if noisy:
        x = x + rng.normal(0, 0.03, x.shape)
    if closed:
        x[:, -1] = x[:, 0]
    return u, x


def parcur_tables():
    tab = Table('curves_parcur.txt', """
parcur cases. Call: parcur(iopt,ipar,idim,m,u,mx,x,w,ub,ue,k,s,nest,n,t,nc,c,fp,wrk,lwrk,iwrk,ier)
through scipy.interpolate.dfitpack.parcur (netlib wrapper). x(idim*(i-1)+j); nc = nest*idim;
c(n*(j-1)+i) given here per coordinate as c1..c<idim> (n-k-1 values each).
ipar=0: u computed by parcur (returned as u_out, ub=0, ue=1). Continuation: s_first then iopt=1.""")

    def call(iopt, ipar, u, x, w, ub, ue, k, s, nest, state=None):
        return parcur_call(iopt, ipar, u, x, w, ub, ue, k, s, nest, state)

    def emit(name, iopt, ipar, u, x, w, ub, ue, k, s, nest, res, table=None, **extra):
        n, t, c, fp, ier, uu, lwrk, _ = res
        idim = x.shape[0]
        out = dict(iopt=iopt, ipar=ipar, idim=idim, k=k, s=s, nest=nest, lwrk=lwrk, ub=ub, ue=ue,
                   u=u, x=x.T.ravel(), w=w)
        out.update(extra)
        out.update(ier=ier, n=n, fp=fp, u_out=uu)
        if ier != 10:
            out['t'] = t[:n]
            for j in range(idim):
                out['c%d' % (j + 1)] = c[n * j:n * j + n - k - 1]
        (table or tab).case(name, **out)

    for idim in (2, 3):
        for k in (1, 2, 3, 4, 5):
            u, x = space_curve(12 + k, idim, noisy=False)
            w = np.ones(len(u))
            nest = len(u) + k + 1
            res = call(0, 1, u, x, w, u[0], u[-1], k, 0.0, nest)
            emit('interp_d%d_k%d' % (idim, k), 0, 1, u, x, w, u[0], u[-1], k, 0.0, nest, res)
        for k in (3, 5):
            u, x = space_curve(40, idim, noisy=True)
            w = np.ones(len(u))
            nest = len(u) + k + 1
            for j, s in enumerate([0.5, 0.1, 0.02]):
                res = call(0, 1, u, x, w, u[0], u[-1], k, s, nest)
                emit('smooth_d%d_k%d_s%d' % (idim, k, j), 0, 1, u, x, w, u[0], u[-1], k, s, nest, res)
            res = call(0, 0, u, x, w, 0.0, 1.0, k, 0.1, nest)
            emit('chord_d%d_k%d' % (idim, k), 0, 0, u, x, w, 0.0, 1.0, k, 0.1, nest, res)
            wv = 1.0 / rng.uniform(0.02, 0.05, len(u))
            res = call(0, 1, u, x, wv, -0.1, 3.2, k, 40.0, nest)
            emit('weighted_d%d_k%d' % (idim, k), 0, 1, u, x, wv, -0.1, 3.2, k, 40.0, nest, res)
            res0 = call(0, 1, u, x, w, u[0], u[-1], k, 0.2, nest)
            res = call(1, 1, u, x, w, u[0], u[-1], k, 0.05, nest, state=res0[-1])
            emit('continue_d%d_k%d' % (idim, k), 1, 1, u, x, w, u[0], u[-1], k, 0.05, nest, res, s_first=0.2)
            res = call(0, 1, u, x, w, u[0], u[-1], k, 1e-4, 2 * k + 5)
            emit('nest_small_d%d_k%d' % (idim, k), 0, 1, u, x, w, u[0], u[-1], k, 1e-4, 2 * k + 5, res)
    # given knots via splprep(task=-1) -> parcur iopt=-1
    u, x = space_curve(30, 3, noisy=True)
    w = np.ones(len(u))
    for k in (1, 3, 5):
        tfull = np.r_[[0.0] * (k + 1), [0.5, 1.0, 1.4, 2.0, 2.5], [3.0] * (k + 1)]
        (tck, uo), fp, ier, msg = splprep(list(x), w=w, u=u, k=k, task=-1, t=tfull, full_output=1, quiet=1)
        t, c, _ = tck
        n = len(t)
        out = dict(iopt=-1, ipar=1, idim=3, k=k, s=0.0, nest=n, ub=0.0, ue=3.0, u=u, x=x.T.ravel(), w=w,
                   n_in=n, t_in=tfull, ier=ier, n=n, fp=fp, t=t)
        for j in range(3):
            out['c%d' % (j + 1)] = np.asarray(c[j])[:n - k - 1]
        tab.case('given_d3_k%d' % k, **out)
    # invalid input
    u, x = space_curve(20, 2, noisy=True)
    w = np.ones(len(u))
    for name, iopt, ipar, k, s, nest, ub in [('bad_k', 0, 1, 0, 0.1, 30, 0.0), ('bad_ipar', 0, 2, 3, 0.1, 30, 0.0),
                                             ('bad_ub', 0, 1, 3, 0.1, 30, 0.5), ('bad_s', 0, 1, 3, -0.1, 30, 0.0),
                                             ('bad_nest_interp', 0, 1, 3, 0.0, 22, 0.0)]:
        try:
            res = call(iopt, ipar, u, x, w, ub, 3.0, k, s, nest)
        except Exception as e:
            print('skipped', name, e)
            continue
        assert res[4] == 10, (name, res[4])
        emit(name, iopt, ipar, u, x, w, ub, 3.0, k, s, nest, res)
    # the p-iteration gives up (see search_draw)
    for name, seed, lo, trial, ier in PROVOKED['parcur']:
        u, x, k, s = search_replay('parcur', seed, lo, trial)
        w = np.ones(len(u))
        res = call(0, 1, u, x, w, u[0], u[-1], k, s, len(u) + k + 1)
        assert res[4] == ier, (name, res[4], ier)
        emit(name, 0, 1, u, x, w, u[0], u[-1], k, s, len(u) + k + 1, res)
    tab.write()

    tab = Table('curves_clocur.txt', """
clocur cases. Call: clocur(iopt,ipar,idim,m,u,mx,x,w,k,s,nest,n,t,nc,c,fp,wrk,lwrk,iwrk,ier)
through scipy.interpolate.splprep(per=1) (scipy's _fitpack._parcur calls clocur when per=1;
nest and lwrk as given here). First and last points equal. ipar=0: u computed by clocur
(u_out). c(n*(j-1)+i) given per coordinate as c1..c<idim> (n-k-1 values each).""")
    for idim in (2, 3):
        for k in (1, 2, 3, 4, 5):
            for j, s in enumerate([0.0, 0.3, 0.05]):
                u, x = space_curve(18 + 2 * k, idim, noisy=(s > 0), closed=True)
                m = len(u)
                w = np.ones(m)
                ipar = 1 if (k + j) % 2 == 0 else 0
                nest = m + 2 * k
                (tck, uo), fp, ier, msg = splprep(list(x.copy()), w=w, u=(u if ipar else None), k=k, s=s, per=1,
                                                  nest=nest, full_output=1, quiet=1)
                t, c, _ = tck
                n = len(t)
                lwrk = m * (k + 1) + nest * (7 + idim + 5 * k)
                out = dict(iopt=0, ipar=ipar, idim=idim, k=k, s=s, nest=nest, lwrk=lwrk, u=u, x=x.T.ravel(), w=w,
                           ier=ier, n=n, fp=fp, u_out=uo, t=t)
                for d in range(idim):
                    out['c%d' % (d + 1)] = np.asarray(c[d])[:n - k - 1]
                tab.case('closed_d%d_k%d_s%d' % (idim, k, j), **out)
    # nest too small for the knots s needs (ier = 1): clocur through _parcur(per=1)
    # with nest = 2k+6 (splprep passes nest on unchanged as well). The shared
    # generator's state is restored afterwards so that later tables stay as they were.
    kept_state = rng.get_state()
    for idim, k in [(2, 3), (3, 5)]:
        u, x = space_curve(40, idim, noisy=True, closed=True)
        w = np.ones(len(u))
        nest = 2 * k + 6
        res = parcur_call(0, 1, u, x, w, u[0], u[-1], k, 1e-4, nest, per=1)
        assert res[4] == 1, res[4]
        emit('nest_small_d%d_k%d' % (idim, k), 0, 1, u, x, w, u[0], u[-1], k, 1e-4, nest, res, table=tab)
    rng.set_state(kept_state)
    for name, seed, lo, trial, ier in PROVOKED['clocur']:
        u, x, k, s = search_replay('clocur', seed, lo, trial)
        w = np.ones(len(u))
        nest = len(u) + 2 * k
        res = parcur_call(0, 1, u, x, w, u[0], u[-1], k, s, nest, per=1)
        assert res[4] == ier, (name, res[4], ier)
        emit(name, 0, 1, u, x, w, u[0], u[-1], k, s, nest, res, table=tab)
    tab.write()


# ---------------------------------------------------------------- evaluation
def eval_tables():
    tab = Table('curves_eval.txt', """
Evaluation cases on splines made by splrep: splev(t,n,c,k,x,y,m,ier) with points outside
the base interval (scipy splev with ext=3 clamps like netlib); splder for nu=1..k at points
clipped to [t(k+1),t(n-k)] (y<nu>); spalde (all derivatives, d(j) of point i at
index (i-1)*(k+1)+j); insert(iopt=0,...) of xins (tt, and cc: its nn-k-1 coefficients); splint(a,b) values; sproot
zeros (k=3). Keys: k, t, c (length n), x, y, y1..y<k>, d, xins, tt, cc, ab (pairs), integrals,
zeros.""")
    for k in range(1, 6):
        x, y = data_1d(25, noisy=True)
        tck = splrep(x, y, k=k, s=0.05)
        t, c, _ = tck
        n = len(t)
        xe = np.sort(np.r_[rng.uniform(-0.5, 4.5, 30), t[k + 1:n - k - 1], x[0], x[-1]])
        yv = splev(xe, tck, ext=3)
        xc = np.clip(xe, t[k], t[n - k - 1])
        out = dict(k=k, t=t, c=c, x=xe, y=yv)
        for nu in range(1, k + 1):
            out['y%d' % nu] = splev(xc, tck, der=nu)
        xa = np.sort(rng.uniform(0.0, 4.0, 7))
        xa = np.r_[xa, t[k + 2], 4.0]
        out['xa'] = xa
        out['d'] = np.array([spalde(xi, tck) for xi in xa]).ravel()
        xins = 1.2345
        tt, cc, _ = insert(xins, tck)
        out['xins'] = xins
        out['tt'] = tt
        # only the n-k-1 meaningful coefficients: scipy's insert leaves the rest
        # of its array uninitialised (it changed from run to run)
        out['cc'] = cc[:len(tt) - k - 1]
        ab = np.array([[0.0, 4.0], [0.3, 2.9], [2.9, 0.3], [-1.0, 5.0], [1.0, 1.0]])
        out['ab'] = ab.ravel()
        out['integrals'] = [splint(a, b, tck) for a, b in ab]
        if k == 3:
            yz = y - 0.6
            tckz = splrep(x, yz, k=3, s=0.05)
            zz = sproot(tckz, mest=20)
            out['tz'] = tckz[0]
            out['cz'] = tckz[1]
            out['zeros'] = zz
        tab.case('spline_k%d' % k, **out)
    tab.write()


# (name, search seed, lowest log10 of s/sum y^2, trial, ier) found by search_run,
# taking only cases whose fp and coefficients the genuine FITPACK reproduces to
# 1e-11 when the data are perturbed at 1e-15 (search_run prints that sensitivity):
# most ier = 3 and nearly all ier = 2 cases are rounding-chaotic (fp changing by
# 1e-8 up to 100 % under such perturbations) and cannot serve as references.
# ier = 2 of parcur and clocur: every case found (parcur seeds 1, 2, 4; clocur
# seed 6) changes fp by 100 % or changes ier under such perturbations, so none is
# tabulated (see the report of the fitpack audit; percur's one is below).
PROVOKED = {
    'percur': [('maxit_a', 2, -10, 925, 3), ('maxit_b', 2, -10, 1463, 3)],
    'parcur': [('maxit_a', 1, -10, 194, 3), ('maxit_b', 1, -10, 387, 3)],
    'clocur': [('closed_maxit_a', 1, -10, 532, 3), ('closed_maxit_b', 1, -10, 612, 3)],
}


if __name__ == '__main__':
    if len(sys.argv) > 1 and sys.argv[1] == '--search':
        search_run(sys.argv[2], int(sys.argv[3]), float(sys.argv[4]) if len(sys.argv) > 4 else -16.0)
        sys.exit(0)
    curfit_tables()
    percur_tables()
    parcur_tables()
    eval_tables()
