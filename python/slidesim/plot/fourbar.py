"""Plots a four-bar result (scenario fourbar): the crank, coupler and rocker
angles over time in degrees, the rocker angle over the crank angle (the
transmission), the energy and the loop-closure residual.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

from .common import DEGREES
from .multibody import coordinates, energy, suptitle

SCENARIOS = ("fourbar",)


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
    g = "/fourbar"
    t = r[g + "/time"].values
    crank = r[g + "/coordinates/crank_angle/value"].values
    fig = plt.figure(figsize=(13, 8))
    ax = fig.add_subplot(2, 2, 1)
    coordinates(ax, r, g)
    for name in sorted(r.file[g + "/dependent"]):
        ax.plot(t, r[f"{g}/dependent/{name}"].values * DEGREES, "--", label=f"{name} [deg]")
    ax.legend(fontsize=8)
    ax.set_ylabel("angle [deg]")
    ax = fig.add_subplot(2, 2, 2)
    ax.plot((crank * DEGREES) % 360, r[g + "/dependent/rocker_angle"].values * DEGREES, ".", ms=2)
    ax.set_xlabel("crank angle mod 360 [deg]")
    ax.set_ylabel("rocker angle [deg]")
    ax.set_title("transmission")
    ax.grid(True)
    energy(fig.add_subplot(2, 2, 3), r, g)
    ax = fig.add_subplot(2, 2, 4)
    floor = 1e-17   # exact closures (residual 0) are drawn here
    ax.semilogy(t, np.maximum(r[g + "/closure_residual"].values, floor))
    ax.set_ylim(floor / 2, None)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("closure residual [m]")
    ax.set_title("loop closure (0 drawn at 1e-17)")
    ax.grid(True)
    suptitle(fig, r)
    fig.tight_layout()
    return fig
