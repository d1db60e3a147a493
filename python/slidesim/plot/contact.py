"""Plots a contact result (scenario contact): the paths of the bodies and of
the contact points in 3-D, the bodies' angular velocities (a spin's angle
grows without bound, its rate tells more), the contacts' normal forces and sliding speeds, and the energy. (For the spinning
egg against Moffatt-Shimomura see slidesim-plot --kind egg.)

A run with flights (a contact that can open, `start = 'open'`) also shows
the gap of each such contact; on every time plot its flight phases (the
records where /contact/contacts/<c>/open is 1 for every such contact) are
shaded, and its impacts
(/contact/impacts) are marked where they happened (3-D, the legend naming
the bodies that met), when (vertical lines) and how fast the body approached
(the gap plot's labels).

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import re

import numpy as np

from .common import equal_axes_3d
from .multibody import body_paths, contact_forces, energy, suptitle

SCENARIOS = ("contact",)
FLIGHT_COLOUR = "tab:cyan"
IMPACT_COLOUR = "tab:red"


def open_intervals(t, is_open):
    """The (start, end) times of the runs of records where a contact is open."""
    runs, start = [], None
    for i, flag in enumerate(is_open):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            runs.append((t[start], t[i - 1]))
            start = None
    if start is not None:
        runs.append((t[start], t[-1]))
    return runs


def flights(r, g, t, contacts):
    """{the contacts that can open: the flight's intervals}, none without
    them. The flights are the records where all of them are open: the body
    touches none (several are the surfaces one body may land on)."""
    names = [name for name in contacts if f"{g}/contacts/{name}/open" in r]
    if not names:
        return {}
    is_open = np.all([r[f"{g}/contacts/{name}/open"].values != 0 for name in names], axis=0)
    return {", ".join(names): open_intervals(t, is_open)}


def impacts(r, g):
    """The impacts table as a dict of arrays (empty without impacts)."""
    if g + "/impacts/time" not in r:
        return {}
    table = {key: r[f"{g}/impacts/{key}"].values for key in ("time", "normal_speed_before", "contact")}
    for key in ("body_1", "body_2"):   # results before they were written have neither
        if f"{g}/impacts/{key}" in r:
            table[key] = r[f"{g}/impacts/{key}"].values
    if g + "/impacts/position" in r:
        table["position"] = r[g + "/impacts/position"].values
    return table


def body_names(r):
    """The &body names in the input's order (the impacts table's body_1 and
    body_2 count them from 1; 0 is the ground)."""
    text = r.file["/input/namelist"].asstr()[()] if "/input/namelist" in r.file else ""
    groups = re.findall(r"&body\b(.*?)(?=&\w|\Z)", text, flags=re.S | re.I)
    names = [re.search(r"\bname\s*=\s*(['\"])(.*?)\1", group, flags=re.S | re.I) for group in groups]
    return ["ground"] + [m.group(2) if m else "?" for m in names]


def impact_pairs(r, table):
    """Which bodies met at the impacts ("ball on ground"), in order of first
    meeting, comma-separated ("" without the bodies columns)."""
    if "body_1" not in table:
        return ""
    names = body_names(r)

    def name(k):
        return names[k] if 0 <= k < len(names) else f"body {k}"
    pairs = [f"{name(b2)} on {name(b1)}" for b1, b2 in zip(table["body_1"], table["body_2"])]
    return ", ".join(dict.fromkeys(pairs))


def shade_flights(ax, phases, label=True):
    """The flight phases as shaded spans (the legend names them once)."""
    for k, (name, intervals) in enumerate(phases.items()):
        for j, (start, end) in enumerate(intervals):
            ax.axvspan(start, end, color=FLIGHT_COLOUR, alpha=0.12 + 0.08 * k, lw=0, gid="flight",
                       label=f"in flight ({name} open)" if label and j == 0 else None)


def impact_events(table):
    """(time, approach speed) of each impact event: the table's rows of one
    time are one impact at several contacts (a ball landing on a cart: the
    hit and the cart's feet, which pass the impulse on at 0 m/s), labelled
    once with its fastest approach."""
    events = {}
    for time, speed in zip(table.get("time", []), table.get("normal_speed_before", [])):
        events[time] = max(events.get(time, 0.0), abs(speed))
    return list(events.items())


def mark_impact_times(ax, table):
    for j, (time, _) in enumerate(impact_events(table)):
        ax.axvline(time, color=IMPACT_COLOUR, ls="--", lw=0.7, label="impact" if j == 0 else None)


def gaps(ax, r, g, t, phases, table, contacts):
    """The gap of each contact that can open over time, its impacts labelled
    with the approach speed."""
    for name in contacts:
        path = f"{g}/measurements/{name}.gap"
        if f"{g}/contacts/{name}/open" not in r:
            continue
        if path in r:
            ax.plot(t, r[path].values, lw=1, label=f"{name} gap")
    shade_flights(ax, phases)
    for j, (time, speed) in enumerate(impact_events(table)):
        ax.plot(time, 0.0, "v", color=IMPACT_COLOUR, ms=6, label="impact (approach speed)" if j == 0 else None)
        # upright: impacts that follow closely (the last bounces) do not overlap
        ax.annotate(f"{speed:.3g} m/s", (time, 0.0), xytext=(0, 6), textcoords="offset points",
                    ha="center", va="bottom", rotation=90, fontsize=7, color=IMPACT_COLOUR, gid="impact")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("gap [m]")
    ax.set_title("gaps of the contacts that can open (0: touching), impacts")
    ax.grid(True)
    ax.legend(fontsize=8, loc="upper right")


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
    g = "/contact"
    t = r[g + "/time"].values
    contacts = sorted(r.file[g + "/contacts"]) if g + "/contacts" in r else []
    phases = flights(r, g, t, contacts)
    table = impacts(r, g)
    rows = 4 if phases else 3
    fig = plt.figure(figsize=(15, 9 + 2.5 * (rows - 3)))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    drawn = [body_paths(ax, r, g)]
    # a contact open all through (bodies that only fly and hit) has no contact point or force
    closed = [name for name in contacts if f"{g}/contacts/{name}/position" in r]
    for name in closed:
        p = r[f"{g}/contacts/{name}/position"].values
        ax.plot(*p.T, "--", lw=0.8, label=f"contact {name}")
        drawn.append(p)
    if "position" in table:
        ax.scatter(*table["position"].T, marker="x", s=40, color=IMPACT_COLOUR, depthshade=False,
                   label=f"impacts ({len(table['time'])}): {impact_pairs(r, table)}".rstrip(": "),
                   gid="impact_position")
    ax.legend(loc="upper left", fontsize=8)
    equal_axes_3d(ax, np.vstack(drawn))
    ax.set_title("paths of the bodies (solid) and contact points (dashed)")
    ax = fig.add_subplot(rows, 2, 2)
    bodies = sorted(r.file[g + "/bodies"])
    for name in bodies:
        w = r[f"{g}/bodies/{name}/angular_velocity"].values
        if len(bodies) == 1:   # one body: its components; several: their magnitudes
            for k, axis in enumerate("xyz"):
                ax.plot(t, w[:, k], lw=1, label=f"{name} ω{axis}")
        else:
            ax.plot(t, np.linalg.norm(w, axis=1), lw=1, label=f"{name} |ω|")
    shade_flights(ax, phases, label=False)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("angular velocity [rad/s]")
    ax.set_title("angular velocities (world axes)" if len(bodies) == 1 else "angular speeds")
    ax.grid(True)
    ax.legend(fontsize=8)
    if phases:
        gaps(fig.add_subplot(rows, 2, 4), r, g, t, phases, table, contacts)
    ax = fig.add_subplot(rows, 2, 2 * rows - 2)
    contact_forces(ax, r, g, [(name, "-") for name in closed], closed)
    shade_flights(ax, phases)
    mark_impact_times(ax, table)
    if phases:
        ax.legend(loc="upper left", fontsize=8)
    ax = fig.add_subplot(rows, 2, 2 * rows)
    energy(ax, r, g)
    shade_flights(ax, phases, label=False)
    mark_impact_times(ax, table)
    if table:
        ax.set_title("energy (each impact removes some: /contact/impacts/energy_lost)")
        ax.legend(fontsize=8)
    suptitle(fig, r)
    fig.tight_layout()
    return fig
