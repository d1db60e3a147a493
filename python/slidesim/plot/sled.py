"""Plots a sled result (scenario sled): the bar's contact paths on the surface
in 3-D with the bar drawn at intervals, the coordinates over time (angles in
degrees), the contact normal forces and the sliding speed, and the energy;
for a vehicle (docs/vehicles.md) also the felt acceleration at its centre of
mass and, on a slide, how high each contact climbs the wall: its distance
along the section from the bottom (/sled/vehicle/<contact>/wall_distance; the
wall angle stops at 90 deg on a flume's vertical wall while the vehicle climbs
on). A vehicle that flies (`&sled may_fly`, /sled/vehicle/open: bit 0 the
rear contact, 1 the front) has its flights shaded on every plot over time
(a contact open; both open, the whole vehicle in the air, darker) and each
landing (/sled/vehicle/flight/landing/time) a dashed line. The wall panel
spans at least 1 cm either side of the bottom, so that a vehicle riding the
bottom line (rounding noise of 1e-15 m) is drawn flat, not as a climb.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

from .common import draw_surface, equal_axes_3d, flag_spans
from .multibody import contact_forces, coordinates, energy, suptitle

SCENARIOS = ("sled",)
FLIGHT_COLOUR = "tab:orange"
BOTH_OPEN = 3
WALL_SPAN = 0.01   # m, the wall panel's least extent either side of the bottom


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
    over_time = [coordinates(fig.add_subplot(rows, 2, 2), r, g)[0]]
    forces = fig.add_subplot(rows, 2, 4)
    contact_forces(forces, r, g, [("rear", "r"), ("front", "b")], ["rear"])
    over_time.append(forces)
    if vehicle:
        over_time.append(fig.add_subplot(rows, 2, 6))
        felt(over_time[-1], r, g, t)
    if on_slide:
        over_time.append(fig.add_subplot(rows, 2, 8))
        wall(over_time[-1], r, g, t)
    over_time.append(fig.add_subplot(rows, 2, 2 * rows))
    energy(over_time[-1], r, g)
    if g + "/vehicle/open" in r:
        for a in over_time:
            mark_flights(a, r, g, t, label=a is forces)
        forces.legend(loc="upper left", fontsize=8)
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
    low, high = ax.get_ylim()
    ax.set_ylim(min(low, -WALL_SPAN), max(high, WALL_SPAN))
    ax.set_xlabel("time [s]")
    ax.set_ylabel("distance along the wall\nfrom the bottom [m, + left]")
    ax.grid(True)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("how high it climbs: distance up the wall (not the wall angle)")


def mark_flights(ax, r, g, t, label=False):
    """The vehicle's flights as shaded spans over time (both contacts open
    darker) and its landings as dashed lines."""
    is_open = r[g + "/vehicle/open"].values
    for j, (start, end) in enumerate(flag_spans(t, is_open != 0)):
        ax.axvspan(start, end, color=FLIGHT_COLOUR, alpha=0.15, lw=0, gid="flight",
                   label="in flight (a contact open)" if label and j == 0 else None)
    for j, (start, end) in enumerate(flag_spans(t, is_open == BOTH_OPEN)):
        ax.axvspan(start, end, color=FLIGHT_COLOUR, alpha=0.3, lw=0, gid="whole_flight",
                   label="whole vehicle in the air" if label and j == 0 else None)
    if g + "/vehicle/flight/landing/time" in r:
        for j, when in enumerate(r[g + "/vehicle/flight/landing/time"].values):
            ax.axvline(when, color=FLIGHT_COLOUR, ls="--", lw=0.9, gid="landing",
                       label="a landing" if label and j == 0 else None)
