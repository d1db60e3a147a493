"""Plots a point-mass result (scenario point_mass): the path on the surface in
3-D, speed and normal force over time (the pressing force: > 0 while the
mass presses on the surface, docs/outputs.md; a value constant to rounding,
as on a horizontal circle in a bowl, drawn flat with its spread in the
legend),
and the energy balance (energy minus friction work, which must stay
constant).

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

from .common import draw_surface, equal_axes_3d, plot_nearly_constant, title

SCENARIOS = ("point_mass",)


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
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
    plot_nearly_constant(ax, t, r[g + "speed"].values, "m/s")
    ax.set_ylabel("speed [m/s]")
    ax.grid(True)
    ax = fig.add_subplot(3, 2, 4)
    plot_nearly_constant(ax, t, r[g + "normal_force"].values, "N")
    ax.set_ylabel("normal force [N]\n(> 0 pressing)")
    ax.grid(True)
    ax = fig.add_subplot(3, 2, 6)
    ax.plot(t, balance - balance[0])
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy − friction work,\nchange [J]")
    ax.grid(True)
    fig.suptitle(title(r))
    fig.tight_layout()
    fig.subplots_adjust(wspace=0.3)   # room for the 3-D axis labels
    return fig
