"""Plots a result file of the geometry optimisation (scenario `optimize`):
- the centerline seen from above and from the side, start and optimum, with
  the design points;
- the acceleration of every ride over time, start (dashed) and optimum;
- the tipping lever arm of every ride over time with the limit (a ride whose
  body lifts off has no lever arm there: the curve breaks);
- the section angle of every ride (0 = the bottom of the tube, positive to the
  +v side) over time;
- for an element design snapped to a catalogue of standard parts
  (docs/design.md): the catalogue design's centerline and largest
  accelerations too, and a table of the design variables (start, optimum,
  nearest allowed, chosen) and of the parts to build with their counts;
- for a robust optimisation over a population (docs/design.md, "Robust
  design over a population"): the rides by member number, the worst member
  of the optimum drawn thick and named in the legend.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

from .common import title as result_title

SCENARIOS = ("optimize",)


def rides(g):
    """(time, acceleration, lever arm, section angle in deg) of each ride."""
    out = []
    k = 1
    while f"ride_{k}" in g:
        r = g[f"ride_{k}"]
        lever = np.asarray(r["lever_arm"][:], dtype=float)
        lever[np.abs(lever) >= 1e29] = np.nan  # not pressed: no lever arm
        out.append((r["time"][:], r["acceleration"][:], lever, np.degrees(r["v"][:] - np.pi / 2)))
        k += 1
    return out


def draw(result, plt, args):
    """The figure of a result; args: the command line's."""
    with result as r:
        g = r.file["/optimize"]
        limit = float(g["lever_limit"][()])
        angles = np.degrees(g["before/start_angle"][:])
        population = "population" in g
        worst = int(g["after/worst_ride"][()]) - 1 if population and "after/worst_ride" in g else None
        c0 = np.asarray(g["centerline_start"][:])
        points = "points_start" in g  # else an element design
        p0 = np.asarray(g["points_start"][:]) if points else None
        before = rides(g["before"])
        optimized = "centerline" in g
        if optimized:
            c1 = np.asarray(g["centerline"][:])
            p1 = np.asarray(g["points"][:]) if points else None
            after = rides(g["after"])
        chosen = rides(g["chosen"]) if "chosen" in g else None
        if chosen:
            c2 = np.asarray(g["centerline_catalogue"][:])
            variables, parts = variable_rows(g), g["parts/list"].asstr()[()].splitlines()
            costs = (float(g["after/acceleration_cost"][()]), float(g["catalogue/acceleration_cost"][0]),
                     float(g["chosen/acceleration_cost"][()]))
        title = result_title(r)

    fig = plt.figure(figsize=(16, 11.5 if chosen else 9))
    grid = fig.add_gridspec(3, 3, height_ratios=[3, 3, 1.6]) if chosen else fig.add_gridspec(2, 3)
    ax = np.array([[fig.add_subplot(grid[i, j]) for j in range(3)] for i in range(2)])
    ax[0, 0].plot(c0[:, 0], c0[:, 1], "k--", label="start")
    if points:
        ax[0, 0].plot(p0[:, 0], p0[:, 1], "ko", ms=4)
    ax[0, 1].plot(arc_length(c0), c0[:, 2], "k--", label="start")
    if optimized:
        ax[0, 0].plot(c1[:, 0], c1[:, 1], "C3", label="optimum")
        if points:
            ax[0, 0].plot(p1[:, 0], p1[:, 1], "C3s", ms=4)
        ax[0, 1].plot(arc_length(c1), c1[:, 2], "C3", label="optimum")
    if chosen:
        ax[0, 0].plot(c2[:, 0], c2[:, 1], "C2", lw=2.5, alpha=0.6, label="catalogue design")
        ax[0, 1].plot(arc_length(c2), c2[:, 2], "C2", lw=2.5, alpha=0.6, label="catalogue design")
    ax[0, 0].set(xlabel="x (m)", ylabel="y (m)", title="centerline from above")
    ax[0, 0].axis("equal")
    ax[0, 0].legend()
    ax[0, 1].set(xlabel="centerline arc length (m)", ylabel="z (m)", title="centerline height")
    ax[0, 1].legend()

    colors = plt.cm.viridis(np.linspace(0, 0.9, len(before)))
    for k, (t, a, lever, wall) in enumerate(before):
        ax[0, 2].plot(t, a, "--", color=colors[k], lw=0.8)
        ax[1, 0].plot(t, lever, "--", color=colors[k], lw=0.8)
        ax[1, 1].plot(t, wall, "--", color=colors[k], lw=0.8)
    if optimized:
        for k, (t, a, lever, wall) in enumerate(after):
            if population:   # many rides: only the worst member in the legend, drawn thick
                label, lw = (f"worst: member {k + 1}", 2.5) if k == worst else (None, 0.8)
            else:
                label, lw = f"{angles[k]:+.0f} deg", 1.5
            ax[0, 2].plot(t, a, color=colors[k], label=label, lw=lw)
            ax[1, 0].plot(t, lever, color=colors[k], lw=lw)
            ax[1, 1].plot(t, wall, color=colors[k], lw=lw)
    ax[0, 2].set(xlabel="time (s)", ylabel="acceleration (m/s^2)",
                 title="acceleration (dashed: start, solid: optimum)")
    if optimized:
        ax[0, 2].legend(title="population" if population else "start angle", fontsize=8)
    for y in (limit, -limit):
        ax[1, 0].axhline(y, color="r", lw=1)
    ax[1, 0].set(xlabel="time (s)", ylabel="lever arm (m)", title="tipping lever arm (red: limit)")
    ax[1, 0].set_ylim(-1, 1)
    ax[1, 1].set(xlabel="time (s)", ylabel="angle from the bottom (deg)", title="position on the wall")

    # the maxima per ride
    x = np.arange(len(before))
    width = 0.27 if chosen else 0.4
    ax[1, 2].bar(x - width / 2 * (2 if chosen else 1), [np.max(a) for _, a, _, _ in before], width, color="0.6",
                 label="start")
    if optimized:
        ax[1, 2].bar(x + (0 if chosen else width / 2), [np.max(a) for _, a, _, _ in after], width, color="C3",
                     label="optimum")
    if chosen:
        ax[1, 2].bar(x + width, [np.max(a) for _, a, _, _ in chosen], width, color="C2", label="catalogue design")
    if population:
        ticks = x[:: max(1, len(x) // 10)]
        ax[1, 2].set_xticks(ticks, [f"{k + 1}" for k in ticks])
        ax[1, 2].set(xlabel="member", ylabel="largest acceleration (m/s^2)", title="largest acceleration")
    else:
        ax[1, 2].set_xticks(x, [f"{a:+.0f}" for a in angles])
        ax[1, 2].set(xlabel="start angle (deg)", ylabel="largest acceleration (m/s^2)",
                     title="largest acceleration")
    ax[1, 2].legend()
    if chosen:
        table = fig.add_subplot(grid[2, :2])
        table.axis("off")
        cells = table.table(cellText=variables, colLabels=["design variable", "unit", "start", "optimum", "nearest",
                                                           "catalogue"], loc="upper center", cellLoc="left")
        cells.auto_set_column_width(list(range(6)))
        cells.scale(1, 1.4)
        nearest = f"{costs[1]:.6g}" if costs[1] < 1e29 else "not ridden"
        table.set_title("design variables (nearest: the allowed value nearest to the optimum)\n"
                        f"acceleration cost (m^2/s^4): optimum {costs[0]:.6g}, nearest {nearest}, "
                        f"catalogue design {costs[2]:.6g}")
        listing = fig.add_subplot(grid[2, 2])
        listing.axis("off")
        listing.set_title("parts to build")
        listing.text(0, 1, "\n".join(parts), va="top", ha="left", fontsize=9, family="monospace", wrap=True)
    fig.suptitle(f"slidesim optimize: {title}")
    fig.tight_layout()
    return fig


def arc_length(c):
    """The arc length along centerline samples c (n, 3)."""
    return np.r_[0, np.cumsum(np.linalg.norm(np.diff(c, axis=0), axis=1))]


def variable_rows(g):
    """The design variables of an element design: name, unit, start, optimum, nearest, catalogue."""
    rows = []
    k = 1
    while f"variables/variable_{k}" in g:
        v = g[f"variables/variable_{k}"]
        unit = v["start"].attrs["units"]
        unit = unit.decode() if isinstance(unit, bytes) else unit
        values = [float(v[name][()]) for name in ("start", "optimum", "nearest", "catalogue")]
        rows.append([v["name"].asstr()[()], "deg" if unit == "degree" else unit, *[f"{x:.4g}" for x in values]])
        k += 1
    return rows
