"""Plots a pendulum result (scenario pendulum): the angles over time in
degrees, the paths of the links' frames in the x-z plane, and the energy.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
from .multibody import body_paths, coordinates, energy, suptitle

SCENARIOS = ("pendulum",)


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
    fig = plt.figure(figsize=(13, 8))
    coordinates(fig.add_subplot(2, 2, 1), r, "/pendulum")
    energy(fig.add_subplot(2, 2, 3), r, "/pendulum")
    ax = fig.add_subplot(1, 2, 2)
    ax.plot([0], [0], "ks", label="hinge")
    body_paths(ax, r, "/pendulum", "xz")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_title("path of the joint between the links\n(the file holds each link's frame origin)")
    ax.grid(True)
    ax.legend(fontsize=8)
    suptitle(fig, r)
    fig.tight_layout()
    return fig
