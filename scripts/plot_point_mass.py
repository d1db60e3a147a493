#!/usr/bin/python3
"""Plots a point-mass result (scenario point_mass): the path on the surface in
3-D, speed and normal force over time, and the energy balance (energy minus
friction work, which must stay constant).

    scripts/plot_point_mass.py RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

from plot_common import command_line, draw_surface, equal_axes_3d, finish, title


def main():
    args, r, plt = command_line(__doc__.splitlines()[0], ("point_mass",))
    g = "/point_mass/"
    t = r[g + "time"].values
    xyz = r[g + "position"].values
    balance = r[g + "energy"].values - r[g + "friction_work"].values
    fig = plt.figure(figsize=(13, 8))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    pts = draw_surface(ax, r)
    ax.plot(*xyz.T, "r-", lw=1.2, label="path")
    ax.plot(*xyz[0], "go", label="start")
    ax.legend(loc="upper left", fontsize=8)
    equal_axes_3d(ax, np.vstack([pts, xyz]))
    ax.set_title("path on the surface")
    ax = fig.add_subplot(3, 2, 2)
    ax.plot(t, r[g + "speed"].values)
    ax.set_ylabel("speed [m/s]")
    ax.grid(True)
    ax = fig.add_subplot(3, 2, 4)
    ax.plot(t, r[g + "normal_force"].values)
    ax.set_ylabel("normal force [N]")
    ax.grid(True)
    ax = fig.add_subplot(3, 2, 6)
    ax.plot(t, balance - balance[0])
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy − friction work,\nchange [J]")
    ax.grid(True)
    fig.suptitle(title(r))
    fig.tight_layout()
    fig.subplots_adjust(wspace=0.3)   # room for the 3-D axis labels
    finish(args, fig, plt)


if __name__ == "__main__":
    main()
