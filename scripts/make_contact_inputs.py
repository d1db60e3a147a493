#!/usr/bin/env python3
"""Writes the point files and geometry files of the B-spline paraboloids in
inputs/contact/paraboloids/, replacing the shipped ones (with --tower only
the tower, into --folder) (thesis 3.5.3.3, table 3.2): 13 x 13 points of
z = (x^2 + y^2)/a^2 on [-w, w]^2, fitted by SURFIT with degree 5 and s = 0.05
(a quintic spline holds them exactly: tests/contact/test_paraboloid_fit.f90).

  bowl_2   a^2 = 3,   w = 2     paraboloid 2 of table 3.2
  bowl_3   a^2 = 0.5, w = 0.5   paraboloid 3 of table 3.2
  tower<n>_<k>, k = 1..n: the tower of n nested bowls, a^2 and w geometric
           from 3 and 2 (k = 1), by the same ratio per level for every n
           (k = 5: 0.5 and 0.5, paraboloid 3's size)

and the tower input inputs/contact/tower5.nml. Pure standard library; run
from the repository root:

  scripts/make_contact_inputs.py                      the shipped inputs
  scripts/make_contact_inputs.py --tower N --folder D  a tower of N (>= 1) bowls:
      D/tower<N>.nml and its bowls in D/paraboloids/ (bench/contact_bench.sh),
      started gently (write_tower)
  optional --duration T: its &solver duration (s, default 10)

Towers of more than 12 bowls or runs longer than 10 s are refused: the runs tested end
there (docs/contact.md, "Towers of any n"); taller ones drive their light top
bowls into conformal contact, where rolling is singular and the run fails
(21 bowls at 8.18 s, 24 at 0.588 s). --untested writes them anyway, with a
warning.
"""
import argparse
import os
import sys

# the tallest tower and the longest run measured to end well: towers of 1 to 12
# run 10 s with the energy conserved to 5e-8 (docs/contact.md, bench/contact_bench.sh)
MAX_TESTED_TOWER = 12
MAX_TESTED_DURATION = 10.0   # s


def write_bowl(folder, name, a2, w):
    with open(os.path.join(folder, name + ".csv"), "w") as f:
        f.write(f"# z = (x^2 + y^2)/{a2!r} on [-{w!r}, {w!r}]^2, 13 x 13 points "
                "(scripts/make_contact_inputs.py)\nx, y, z\n")
        for j in range(13):
            for i in range(13):
                x = -w + 2 * w * i / 12
                y = -w + 2 * w * j / 12
                f.write(f"{x!r}, {y!r}, {(x * x + y * y) / a2!r}\n")
    with open(os.path.join(folder, name + ".geo"), "w") as f:
        f.write(f"! B-spline paraboloid z = (x^2 + y^2)/{a2!r} (scripts/make_contact_inputs.py)\n"
                f"&bspline file = '{name}.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /\n")


def tower_sizes(n):
    """a^2, half width, mass, centre height, inertia (diagonal) of bowl k = 1..n.

    The same ratios from one level to the next for every n (those of a tower of
    five from paraboloid 2's size down to paraboloid 3's): a^2 shrinks by
    (1/6)^(1/4), the half width and the mass by (1/4)^(1/4). A bowl's vertex is
    then 1.57 times as curved as the bowl it rolls in; nearer ratios let the
    contact reach a point of equal curvature (conformal contact, where rolling
    is singular) within a few tens of degrees of relative tilt.
    """
    sizes = []
    for k in range(n):
        a2 = 3 * (1 / 6) ** (k / 4)
        w = 2 * (1 / 4) ** (k / 4)
        mass = 2 * (1 / 4) ** (k / 4)
        rho = a2 / 2                      # radius of curvature at the vertex
        h = 0.4 * rho                     # centre of mass well below it: stable in the bowl below
        i_xy = mass * (0.3 * w) ** 2
        sizes.append((a2, w, mass, h, (i_xy, i_xy, 1.5 * i_xy)))
    return sizes


def write_tower(n, folder="inputs/contact", duration=MAX_TESTED_DURATION, lively=False):
    """The tower input; lively: the shipped tower5's start (bowls 1..5 each
    0.04 m further off the axis than the one below, all tilted by (3, 1.5, 0)
    degrees), else a gentle start (every bowl on the axis of the one below,
    all tilted by 1 degree about x). The lively start drives the small bowls of
    a tower of 6 or more into conformal contact within 0.3 s (docs/contact.md)."""
    sizes = tower_sizes(n)
    bowls = os.path.join(folder, "paraboloids")
    os.makedirs(bowls, exist_ok=True)
    lines = [f"! A tower of {n} B-spline paraboloids (thesis A.6; docs/contact.md), each",
             "! vertex down in the bowl of the one below, the lowest on the table;",
             "! rolling at every contact; written by scripts/make_contact_inputs.py.",
             "&run",
             "  scenario = 'contact'",
             f"  output = 'tower{n}.h5'",
             f"  title = 'tower of {n} rolling B-spline paraboloids, P1'",
             "/",
             "&solver",
             "  method = 'adams', rtol = 1e-11, atol = 1e-10   ! P1",
             f"  duration = {duration!r}, output_step = 5e-3",
             "/",
             "&contact_model gravity = 0.0, 0.0, -9.80665 /",
             "&shape name = 'table', kind = 'plane' /"]
    for k, (a2, w, *_rest) in enumerate(sizes, start=1):
        write_bowl(bowls, f"tower{n}_{k}", a2, w)
        lines.append(f"&shape name = 'bowl{k}', kind = 'bspline', geometry_file = 'paraboloids/tower{n}_{k}.geo' /")
    x = z = 0.0
    for k, (a2, w, mass, h, inertia) in enumerate(sizes, start=1):
        # at rest; the stack rocks and rolls about its stable equilibrium
        step = (0.04 if k <= 5 else 0.0) if lively else 0.0
        tilt = "3, 1.5, 0" if lively else "1, 0, 0"
        x += step
        lines += [f"&body name = 'bowl{k}', mass = {mass:.6g}, centre = 0, 0, {h:.6g}",
                  f"  inertia = {inertia[0]:.6g}, {inertia[1]:.6g}, {inertia[2]:.6g}",
                  f"  position = {x:.4g}, 0.0, {z:.4g}, angles_deg = {tilt} /"]
        # gentle: at the height of the vertex below, so that the point of the
        # bowl below nearest to the origin (where the contact starts) is its
        # vertex; far above a small bowl's centre of curvature it is on the wall
        z += 0.1 if lively else 0.0
    lines.append("&contact name = 'bowl1_on_table', body_1 = 'ground', shape_1 = 'table', side_1 = 1,")
    lines.append("  body_2 = 'bowl1', shape_2 = 'bowl1', side_2 = -1, rolling = .true. /")
    for k in range(2, n + 1):
        lines.append(f"&contact name = 'bowl{k}_in_bowl{k - 1}', body_1 = 'bowl{k - 1}', shape_1 = 'bowl{k - 1}', "
                     "side_1 = 1,")
        lines.append(f"  body_2 = 'bowl{k}', shape_2 = 'bowl{k}', side_2 = -1, rolling = .true. /")
    with open(os.path.join(folder, f"tower{n}.nml"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tower", type=int, help="write only a tower of this many bowls")
    parser.add_argument("--folder", default="inputs/contact", help="where the tower goes")
    parser.add_argument("--duration", type=float, default=MAX_TESTED_DURATION, help="its simulated time, s")
    parser.add_argument("--untested", action="store_true",
                        help=f"write a tower of more than {MAX_TESTED_TOWER} bowls (or longer than "
                             f"{MAX_TESTED_DURATION:g} s) anyway: it may end in a singular contact")
    args = parser.parse_args()
    if args.tower is not None:
        if args.tower < 1:
            parser.error(f"--tower {args.tower}: a tower needs at least 1 bowl")
        if not args.duration > 0:
            parser.error(f"--duration {args.duration}: give the simulated time in s, a number > 0")
        beyond = []
        if args.tower > MAX_TESTED_TOWER:
            beyond.append(f"{args.tower} bowls, more than the {MAX_TESTED_TOWER} tested: taller towers drive "
                          "their light top bowls into conformal contact, where rolling is singular and the run "
                          "fails (21 bowls at 8.18 s, 24 at 0.588 s; docs/contact.md)")
        if args.duration > MAX_TESTED_DURATION:
            beyond.append(f"--duration {args.duration:g} s, longer than the {MAX_TESTED_DURATION:g} s tested")
        if beyond and not args.untested:
            parser.error("--tower " + str(args.tower) + ": " + "; ".join(beyond) +
                         "; add --untested to write it anyway")
        for text in beyond:
            print(f"warning: untested tower: {text}", file=sys.stderr)
        write_tower(args.tower, args.folder, args.duration)
        return
    folder = "inputs/contact/paraboloids"
    os.makedirs(folder, exist_ok=True)
    write_bowl(folder, "bowl_2", 3.0, 2.0)
    write_bowl(folder, "bowl_3", 0.5, 0.5)
    write_tower(5, duration=5.0, lively=True)   # 5 s: every shipped input runs in CI (tests/cli)


if __name__ == "__main__":
    main()
