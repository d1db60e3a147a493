"""Plots a sled result (scenario sled): the bar's contact paths on the surface
in 3-D with the bar drawn at intervals, the coordinates over time (angles in
degrees), the contact normal forces and the sliding speed, and the energy;
for a vehicle (docs/vehicles.md) also the felt acceleration at its centre of
mass and, on a slide, how high each contact climbs the wall: its distance
along the section from the bottom (/sled/vehicle/<contact>/wall_distance; the
wall angle stops at 90 deg on a flume's vertical wall while the vehicle climbs
on).

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

from .common import draw_surface, equal_axes_3d
from .multibody import contact_forces, coordinates, energy, suptitle

SCENARIOS = ("sled",)


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
    g = "/sled"
    t = r[g + "/time"].values
    rear = r[g + "/contacts/rear/position"].values
    front = r[g + "/contacts/front/position"].values
    vehicle = g + "/vehicle/felt_acceleration" in r
    on_slide = g + "/vehicle/rear/wall_distance" in r
    rows = 3 + vehicle + on_slide
    fig = plt.figure(figsize=(15, 9 + 2 * on_slide))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    pts = draw_surface(ax, r, alpha=0.25)
    ax.plot(*rear.T, "r-", lw=1, label="rear contact")
    ax.plot(*front.T, "b-", lw=1, label="front contact")
    for i in np.linspace(0, len(t) - 1, 12).astype(int):
        ax.plot(*np.column_stack([rear[i], front[i]]), "k-", lw=2)
    body = "the vehicle" if vehicle else "the bar"
    ax.plot([], [], "k-", lw=2, label=f"{body} (12 instants, rear to front contact)")
    ax.legend(loc="upper left", fontsize=8)
    equal_axes_3d(ax, np.vstack([pts, rear, front]))
    ax.set_title(f"{body} on the surface")
    coordinates(fig.add_subplot(rows, 2, 2), r, g)
    contact_forces(fig.add_subplot(rows, 2, 4), r, g, [("rear", "r"), ("front", "b")], ["rear"])
    if vehicle:
        felt(fig.add_subplot(rows, 2, 6), r, g, t)
    if on_slide:
        wall(fig.add_subplot(rows, 2, 8), r, g, t)
    energy(fig.add_subplot(rows, 2, 2 * rows), r, g)
    suptitle(fig, r)
    fig.tight_layout()
    return fig


def felt(ax, r, g, t):
    """The felt acceleration at the vehicle's centre of mass along its axes, in g."""
    f = r[g + "/vehicle/felt_acceleration"].values
    for k, (name, style) in enumerate([("longitudinal", "g-"), ("lateral", "m-"), ("normal", "k-")]):
        ax.plot(t, f[:, k], style, label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("felt acceleration [g]")
    ax.grid(True)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("felt acceleration at the centre of mass")


def wall(ax, r, g, t):
    """How high each contact climbs: its distance along the section from the
    bottom (+ to the left, towards +v), over time."""
    for name, style in (("rear", "r-"), ("front", "b-")):
        ax.plot(t, r[f"{g}/vehicle/{name}/wall_distance"].values, style, label=f"{name} contact")
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("distance along the wall\nfrom the bottom [m, + left]")
    ax.grid(True)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("how high it climbs: distance up the wall (not the wall angle)")
