"""Plots a ride result file (scenario `ride`, docs/rider.md):
- the unrolled slide: the distance along the wall from the bottom of the
  three contacts (pelvis, heels, back: /rider/<c>/wall_distance) and of the
  water band between its edges (the table's v measured along the section on
  the surface grid) over the centerline arc length (0 = the bottom, positive
  to the left); the distance, not the wall angle, which stops at 90 deg on
  a flume's vertical wall while the rider climbs on (the angles are in the
  summary and the CSV);
- the rider's speed and the water's, with the user's speed limit across
  the ride and the exit-speed limit as a short line at the exit only;
- the felt accelerations in g (longitudinal, lateral, normal at the pelvis)
  with the user's acceleration limits;
- the normal forces of the three contacts;
- a 3-D view of the slide with the water band and the contacts' paths.
A ride that ended ejected (a contact went over the top of a wall: /rider
attribute `ejected`) marks where: a vertical line at
/evaluation/ejected_arc_length on the plots over arc length, a cross where
the contact left the slide on the unrolled slide and in 3-D.
A ride with flights (`may_fly`, /rider/airborne: the open contacts, bit 0
pelvis, 1 heels, 2 back) shades each flight (any contact open) over the
pelvis's arc length on the plots over arc length, the whole rider's flights
(every contact open) darker, and marks each landing
(/evaluation/flight/landing): a dashed line where the pelvis was at the
landing's time, and a diamond on the unrolled slide at the landing
contact's own arc length and wall distance (in its colour), labelled with the drop height
v_n^2/(2g).

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import math

import numpy as np

from .common import flag_spans, title

CONTACTS = ("pelvis", "heels", "back")
FLIGHT_COLOUR = "tab:orange"
ALL_OPEN = 7
COLOURS = {"pelvis": "tab:red", "heels": "tab:green", "back": "tab:purple"}
AXES = ("longitudinal", "lateral", "normal")
SCENARIOS = ("ride",)


def rows(a):
    """Fortran (3 x n) arrays come as (n, 3); keep them so."""
    a = np.asarray(a)
    return a.T if a.ndim == 2 and a.shape[0] == 3 and a.shape[1] != 3 else a


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def read(f):
    """The ride's arrays from an open h5py.File."""
    d = {}
    d["status"] = text(f.attrs.get("status", "?"))
    r = f["/rider"]
    d["outcome"] = text(r.attrs.get("outcome", "?"))
    d["s"] = r["arc_length"][:]
    d["speed"] = r["speed"][:]
    d["felt"] = rows(r["acceleration_g"][:])
    for c in CONTACTS:
        d[c] = {k: r[f"{c}/{k}"][:] for k in ("arc_length", "wall_distance", "normal_force", "in_water")}
        d[c]["position"] = rows(r[f"{c}/position"][:])
    w = f["/water"]
    d["ejected"] = text(r.attrs["ejected"]) if "ejected" in r.attrs else None
    if d["ejected"] and "/evaluation/ejected_arc_length" in f:
        d["ejected_s"] = float(f["/evaluation/ejected_arc_length"][()])
    d["flights"], d["whole_flights"], d["landings"] = [], [], []
    if "airborne" in r:
        d["flights"] = flag_spans(d["s"], r["airborne"][:] != 0)
        d["whole_flights"] = flag_spans(d["s"], r["airborne"][:] == ALL_OPEN)
    if "/evaluation/flight/landing/time" in f:
        land = f["/evaluation/flight/landing"]
        time = r["time"][:]
        n = len(land["time"])
        contact = land["contact"][:] if "contact" in land else np.full(n, 2)
        for t, s_contact, h, c in zip(land["time"][:], land["arc_length"][:], land["drop_height"][:], contact):
            d["landings"].append({"s": float(np.interp(t, time, d["s"])), "contact_s": float(s_contact),
                                  "contact": CONTACTS[int(round(c)) - 1], "drop_height": float(h)})
    d["water_s"] = w["arc_length"][:]
    d["water_speed"] = w["speed"][:]
    t = f["/water/table"]
    d["table_s"] = t["arc_length"][:]
    g = f["/geometry/surface"]
    d["grid"] = [g[k][:] for k in ("x", "y", "z")]
    along = section_distance(g["u"][:], g["v"][:], d["grid"])
    for key, name in (("table_left", "v_left"), ("table_right", "v_right"), ("table_mid", "v")):
        d[key] = along(t["u"][:], t[name][:])
    d["water_left"] = rows(w["left_point"][:])
    d["water_right"] = rows(w["right_point"][:])
    d["limits"] = []
    if "/evaluation/limits" in f:
        for name in f["/evaluation/limits"]:
            lim = f[f"/evaluation/limits/{name}"]
            entry = {"quantity": text(lim["quantity"][()]), "verdict": text(lim["verdict"][()]).strip()}
            for b in ("minimum", "maximum"):
                if b in lim:
                    entry[b] = float(lim[b][()])
            d["limits"].append(entry)
    return d


def section_distance(grid_u, grid_v, grid):
    """A function (u, v) -> the distance along the section at u from its
    bottom (v = pi/2, as the contacts' wall_distance) to v, positive towards
    +v (left): the chords of the surface grid's rows either side of u,
    summed from the bottom, interpolated linearly in u (the grid's chords
    shorten a circle of radius r by about r dv^2/24 per radian of it)."""
    points = np.stack(grid, axis=-1)                       # (n_u, n_v, 3)
    chords = np.linalg.norm(np.diff(points, axis=1), axis=2)
    along = np.concatenate([np.zeros((len(grid_u), 1)), np.cumsum(chords, axis=1)], axis=1)
    along -= np.array([np.interp(math.pi / 2, grid_v, row) for row in along])[:, None]

    def at(u, v):
        k = np.clip(np.searchsorted(grid_u, u), 1, len(grid_u) - 1)
        w = np.clip((u - grid_u[k - 1]) / (grid_u[k] - grid_u[k - 1]), 0.0, 1.0)
        return np.array([(1 - wi) * np.interp(vi, grid_v, along[ki - 1]) + wi * np.interp(vi, grid_v, along[ki])
                         for vi, ki, wi in zip(v, k, w)])
    return at


def mark_flights(ax, d, label=False):
    """The flights as shaded spans (the whole rider's darker) and their
    landings as dashed lines (over the pelvis's arc length)."""
    for j, (start, end) in enumerate(d["flights"]):
        ax.axvspan(start, end, color=FLIGHT_COLOUR, alpha=0.15, lw=0, gid="flight",
                   label="in flight (a contact open)" if label and j == 0 else None)
    for j, (start, end) in enumerate(d["whole_flights"]):
        ax.axvspan(start, end, color=FLIGHT_COLOUR, alpha=0.3, lw=0, gid="whole_flight",
                   label="whole rider in the air" if label and j == 0 else None)
    for j, landing in enumerate(d["landings"]):
        ax.axvline(landing["s"], color=FLIGHT_COLOUR, ls="--", lw=0.9, gid="landing",
                   label="a landing" if label and j == 0 else None)


def mark_landings_on_slide(ax, d):
    """Each landing at its contact's arc length on the unrolled slide, with
    its drop height."""
    seen = set()
    for j, landing in enumerate(d["landings"]):
        c = landing["contact"]
        path = d[c]
        height = np.interp(landing["contact_s"], path["arc_length"], path["wall_distance"])
        ax.plot([landing["contact_s"]], [height], "D", color=COLOURS[c], mec="k", ms=7, gid="landing",
                label=f"{c}' landing" if c.endswith("s") and c not in seen else
                (f"{c}'s landing" if c not in seen else None), zorder=5)
        seen.add(c)
        ax.annotate(f"{100 * landing['drop_height']:.3g} cm drop", (landing["contact_s"], height),
                    textcoords="offset points", xytext=(4, 6 + 10 * (j % 3)), fontsize=7, gid="landing")


def mark_ejection(ax, d, label=False):
    """The arc length where the rider was ejected, as a vertical line."""
    if d.get("ejected_s") is not None:
        ax.axvline(d["ejected_s"], color="k", ls="-.", lw=1.0, gid="ejection",
                   label=f"ejected ({d['ejected']} over the wall)" if label else None)


def mark_ejected_contact(ax, d, x, y, z=None):
    """A cross where the ejected contact left the slide (its last record)."""
    if not d.get("ejected"):
        return
    points = (x[-1], y[-1]) if z is None else (x[-1], y[-1], z[-1])
    ax.plot(*[[p] for p in points], "X", color=COLOURS[d["ejected"]], mec="k", ms=11, gid="ejection",
            label=f"{d['ejected']} ejected here", zorder=5)


def draw(result, plt, args):
    """The figure of a result; args: the command line's."""
    d = read(result.file)
    s = d["s"]

    fig = plt.figure(figsize=(15, 14))
    fig.suptitle(title(result, f": {d['outcome']}"), fontsize=9)
    grid = fig.add_gridspec(3, 2, height_ratios=[1, 1, 1.7])

    ax = fig.add_subplot(grid[0, 0])
    ax.fill_between(d["table_s"], d["table_right"], d["table_left"], color="tab:blue", alpha=0.25,
                    label="water band")
    ax.plot(d["table_s"], d["table_mid"], color="tab:blue", lw=0.6, label="water middle")
    for c in CONTACTS:
        ax.plot(d[c]["arc_length"], d[c]["wall_distance"], color=COLOURS[c], lw=1.0, label=c)
    if d["ejected"]:
        mark_ejected_contact(ax, d, d[d["ejected"]]["arc_length"], d[d["ejected"]]["wall_distance"])
    mark_landings_on_slide(ax, d)
    ax.set_xlabel("arc length along the slide (m)")
    ax.set_ylabel("distance along the wall from the bottom (m, + left)")
    ax.set_title("the unrolled slide: contacts and water, distance up the wall")
    ax.legend(fontsize=7, loc="lower left")
    ax.grid(alpha=0.3)

    ax = fig.add_subplot(grid[0, 1])
    ax.plot(s, d["speed"], color="k", label="rider (pelvis)")
    ax.plot(d["water_s"], d["water_speed"], color="tab:blue", lw=0.8, label="water")
    for lim in d["limits"]:
        if lim["quantity"] == "speed" and "maximum" in lim:
            ax.axhline(lim["maximum"], color="tab:red", ls="--", lw=0.8, gid="limit",
                       label=f"speed limit ({lim['verdict']})")
        elif lim["quantity"] == "exit_speed" and "maximum" in lim:   # judged at the exit only
            ax.plot([s[-1] - 0.08 * (s[-1] - s[0]), s[-1]], [lim["maximum"]] * 2, color="tab:red", lw=2.0,
                    gid="limit", label=f"exit_speed limit, at the exit ({lim['verdict']})")
    mark_ejection(ax, d, label=True)
    mark_flights(ax, d, label=True)
    ax.set_xlabel("arc length (m)")
    ax.set_ylabel("speed (m/s)")
    ax.set_title("speed")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    ax = fig.add_subplot(grid[1, 0])
    for k, name in enumerate(AXES):
        ax.plot(s, d["felt"][:, k], lw=0.9, label=name)
        for lim in d["limits"]:
            if lim["quantity"] == "acceleration_" + name:
                for b in ("minimum", "maximum"):
                    if b in lim:
                        ax.axhline(lim[b], color=ax.lines[-1].get_color(), ls="--", lw=0.8,
                                   label=f"{name} {b} ({lim['verdict']})")
    mark_ejection(ax, d)
    mark_flights(ax, d)
    ax.set_xlabel("arc length (m)")
    ax.set_ylabel("felt acceleration (g)")
    ax.set_title("felt accelerations at the pelvis (a - g)/|g|")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    ax = fig.add_subplot(grid[1, 1])
    for c in CONTACTS:
        ax.plot(s, d[c]["normal_force"], color=COLOURS[c], lw=0.9, label=c)
    for lim in d["limits"]:
        if lim["quantity"] == "normal_force" and "minimum" in lim:
            ax.axhline(lim["minimum"], color="tab:red", ls="--", lw=0.8, label=f"minimum ({lim['verdict']})")
    ax.axhline(0, color="k", lw=0.5)
    mark_ejection(ax, d, label=True)
    mark_flights(ax, d, label=True)
    ax.set_xlabel("arc length (m)")
    ax.set_ylabel("normal force (N)")
    ax.set_title("normal forces (0: lift-off)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)

    ax = fig.add_subplot(grid[2, :], projection="3d")
    x, y, z = d["grid"]
    ax.plot_surface(x, y, z, color="0.85", alpha=0.25, linewidth=0, rstride=4, cstride=2)
    left, right = d["water_left"], d["water_right"]
    ax.plot(left[:, 0], left[:, 1], left[:, 2], color="tab:blue", lw=0.6)
    ax.plot(right[:, 0], right[:, 1], right[:, 2], color="tab:blue", lw=0.6, label="water edges")
    for c in CONTACTS:
        p = d[c]["position"]
        ax.plot(p[:, 0], p[:, 1], p[:, 2], color=COLOURS[c], lw=1.0, label=c)
    if d["ejected"]:
        p = d[d["ejected"]]["position"]
        mark_ejected_contact(ax, d, p[:, 0], p[:, 1], p[:, 2])
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.set_box_aspect((np.ptp(x), np.ptp(y), np.ptp(z)))   # true proportions
    ax.view_init(elev=35, azim=-60)
    ax.set_title("the slide, the water band and the contacts' paths")
    ax.legend(fontsize=7)

    fig.tight_layout()
    return fig
