#!/usr/bin/env python3
"""Writes the point files and geometry files of the B-spline paraboloids in
inputs/contact/paraboloids/ (thesis 3.5.3.3, table 3.2): 13 x 13 points of
z = (x^2 + y^2)/a^2 on [-w, w]^2, fitted by SURFIT with degree 5 and s = 0.05
(a quintic spline holds them exactly: tests/contact/test_paraboloid_fit.f90).

  bowl_2   a^2 = 3,   w = 2     paraboloid 2 of table 3.2
  bowl_3   a^2 = 0.5, w = 0.5   paraboloid 3 of table 3.2
  tower<n>_<k>, k = 1..n: the tower of n nested bowls, a^2 and w geometric
           from 3 and 2 (k = 1) to 0.5 and 0.5 (k = n)

and the tower input inputs/contact/tower5.nml. Pure standard library; run
from the repository root: scripts/make_contact_inputs.py
"""
import os

FOLDER = "inputs/contact/paraboloids"


def write_bowl(name, a2, w):
    with open(os.path.join(FOLDER, name + ".csv"), "w") as f:
        f.write(f"# z = (x^2 + y^2)/{a2!r} on [-{w!r}, {w!r}]^2, 13 x 13 points "
                "(scripts/make_contact_inputs.py)\nx, y, z\n")
        for j in range(13):
            for i in range(13):
                x = -w + 2 * w * i / 12
                y = -w + 2 * w * j / 12
                f.write(f"{x!r}, {y!r}, {(x * x + y * y) / a2!r}\n")
    with open(os.path.join(FOLDER, name + ".geo"), "w") as f:
        f.write(f"! B-spline paraboloid z = (x^2 + y^2)/{a2!r} (scripts/make_contact_inputs.py)\n"
                f"&bspline file = '{name}.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /\n")


def tower_sizes(n):
    """a^2, half width, mass, centre height, inertia (diagonal) of bowl k = 1..n."""
    sizes = []
    for k in range(n):
        s = k / (n - 1)
        a2 = 3 * (0.5 / 3) ** s
        w = 2 * (0.5 / 2) ** s
        mass = 2 * 0.25 ** s
        rho = a2 / 2                      # radius of curvature at the vertex
        h = 0.4 * rho                     # centre of mass well below it: stable in the bowl below
        i_xy = mass * (0.3 * w) ** 2
        sizes.append((a2, w, mass, h, (i_xy, i_xy, 1.5 * i_xy)))
    return sizes


def write_tower(n):
    sizes = tower_sizes(n)
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
             "  duration = 20.0, output_step = 5e-3",
             "/",
             "&contact_model gravity = 0.0, 0.0, -9.81 /",
             "&shape name = 'table', kind = 'plane' /"]
    for k, (a2, w, *_rest) in enumerate(sizes, start=1):
        write_bowl(f"tower{n}_{k}", a2, w)
        lines.append(f"&shape name = 'bowl{k}', kind = 'bspline', geometry_file = 'paraboloids/tower{n}_{k}.geo' /")
    z = 0.0
    for k, (a2, w, mass, h, inertia) in enumerate(sizes, start=1):
        # at rest, each a little off the bottom of the bowl below and tilted
        # the same way: the stack rocks and rolls about its stable equilibrium
        lines += [f"&body name = 'bowl{k}', mass = {mass:.6g}, centre = 0, 0, {h:.6g}",
                  f"  inertia = {inertia[0]:.6g}, {inertia[1]:.6g}, {inertia[2]:.6g}",
                  f"  position = {0.04 * k:.3g}, 0.0, {z:.3g}, angles_deg = 3, 1.5, 0 /"]
        z += 0.1
    lines.append("&contact name = 'bowl1_on_table', body_1 = 'ground', shape_1 = 'table', side_1 = 1,")
    lines.append("  body_2 = 'bowl1', shape_2 = 'bowl1', side_2 = -1, rolling = .true. /")
    for k in range(2, n + 1):
        lines.append(f"&contact name = 'bowl{k}_in_bowl{k - 1}', body_1 = 'bowl{k - 1}', shape_1 = 'bowl{k - 1}', "
                     "side_1 = 1,")
        lines.append(f"  body_2 = 'bowl{k}', shape_2 = 'bowl{k}', side_2 = -1, rolling = .true. /")
    with open(f"inputs/contact/tower{n}.nml", "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    os.makedirs(FOLDER, exist_ok=True)
    write_bowl("bowl_2", 3.0, 2.0)
    write_bowl("bowl_3", 0.5, 0.5)
    write_tower(5)


if __name__ == "__main__":
    main()
