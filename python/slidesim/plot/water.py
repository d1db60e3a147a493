"""Plots the water of a result: the unrolled slide (the angle of the
water's middle and of its edges over the centerline arc length, as thesis
fig. 4.11: 0 deg is the bottom, positive to the left) with the stations;
speed and water height over arc length (with several inlets, the flow
rate and where each inlet joined); the water band drawn on the slide
surface in 3-D. The plot of a water result, and of any other result that
holds the water's group /water (a ride, a sled riding in water: --kind
water); a result without it is refused, the message naming the file.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show] [--kind water]
"""
import numpy as np

from .common import DEGREES, draw_surface, equal_axes_3d, title

# what the plot draws from /water (the band's edges: at the samples or at the table's rows)
NEEDED = ("arc_length", "u", "v", "speed", "height", "position")
BAND = (("left_edge_v", "right_edge_v"), ("table/arc_length", "table/v_left", "table/v_right"))


def refusal(r):
    """Why result `r` has no water to plot (None when it has)."""
    if "/water" not in r:
        return ("which holds no water (no group /water): the water plot draws the /water of a water run, "
                "or of a ride or sled that rides in water")
    missing = [name for name in NEEDED if f"/water/{name}" not in r]
    if not any(all(f"/water/{name}" in r for name in band) for band in BAND):
        missing.append("left_edge_v or table/v_left")
    if missing:
        return f"whose group /water lacks {', '.join(missing)}"
    return None


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
    s = r["/water/arc_length"].values
    v = r["/water/v"].values
    speed = r["/water/speed"].values
    height = r["/water/height"].values
    xyz = r["/water/position"].values
    bottom = np.pi / 2   # v of the bottom of a circular section
    # the edges at the samples when the run solved them there, else at the table's rows
    if "/water/left_edge_v" in r:
        band_s, left, right = s, r["/water/left_edge_v"].values, r["/water/right_edge_v"].values
    else:
        band_s = r["/water/table/arc_length"].values
        left, right = r["/water/table/v_left"].values, r["/water/table/v_right"].values

    fig = plt.figure(figsize=(15, 9))
    ax1 = fig.add_subplot(2, 2, 1)
    ax1.plot(s, (v - bottom) * DEGREES, "b-", label="streamline (middle)")
    ax1.fill_between(band_s, (right - bottom) * DEGREES, (left - bottom) * DEGREES, color="tab:blue",
                     alpha=0.25, label="water band")
    if "/water/stations/arc_length" in r:
        reached = r["/water/stations/reached"].values == 1
        ax1.plot(r["/water/stations/arc_length"].values[reached],
                 (r["/water/stations/v_middle"].values[reached] - bottom) * DEGREES, "ko",
                 label="stations (middle of the edges)")
    ax1.set_xlabel("centerline arc length [m]")
    ax1.set_ylabel("angle from the bottom [deg], + left")
    ax1.set_title("unrolled slide (thesis fig. 4.11)")
    ax1.grid(True)
    ax1.legend(fontsize=8)

    ax2 = fig.add_subplot(2, 2, 3)
    ax2.plot(s, speed, "r-")
    ax2.set_xlabel("centerline arc length [m]")
    ax2.set_ylabel("speed [m/s]", color="r")
    ax2.grid(True)
    ax2b = ax2.twinx()
    ax2b.plot(s, height * 1000, "g-")
    ax2b.set_ylabel("water height [mm]", color="g")
    ax2.set_title("speed and height")
    if "/water/inlets/arc_length" in r:   # several inlets: where each joined, and the flow rate
        joined = r["/water/inlets/joined"].values == 1
        for at in r["/water/inlets/arc_length"].values[joined]:
            ax2.axvline(at, color="k", ls=":", lw=1)
        ax2c = ax2.twinx()
        ax2c.spines["right"].set_position(("axes", 1.12))
        ax2c.step(s, r["/water/flow_rate"].values * 1000, "k-", where="post", lw=1)
        ax2c.set_ylabel("flow rate [l/s] (inlets dotted)")
        ax2.set_title("speed, height and flow rate")

    # the whole slide, and a close-up 6 m around where the water climbs highest
    u = r["/water/u"].values
    k = int(np.argmax(np.abs(v - bottom)))
    near = np.abs(s - s[k]) <= 3.0
    for position, (lo, hi), label in ((2, (0, len(s)), "the water band on the slide"),
                                      (4, (np.argmax(near), len(s) - np.argmax(near[::-1])),
                                       f"close-up at {s[k]:.1f} m (largest angle)")):
        ax3 = fig.add_subplot(2, 2, position, projection="3d")
        window = slice(lo, hi)
        pts = draw_surface(ax3, r, alpha=0.15 if position == 2 else 0.3,
                           u_range=(u[window].min(), u[window].max()) if position == 4 else None)
        if "/water/left_point" in r:
            lp, rp = r["/water/left_point"].values[window], r["/water/right_point"].values[window]
            ax3.plot_surface(np.vstack([rp[:, 0], lp[:, 0]]), np.vstack([rp[:, 1], lp[:, 1]]),
                             np.vstack([rp[:, 2], lp[:, 2]]), color="tab:blue", alpha=0.9, linewidth=0)
        ax3.plot(*xyz[window].T, "navy", lw=0.8, label="streamline")
        ax3.legend(loc="upper left", fontsize=8)
        equal_axes_3d(ax3, pts if len(pts) else xyz[window])
        ax3.set_title(label)
        ax3.view_init(elev=35, azim=-60)
    outcome = r.group_attrs("/water").get("outcome", "?")
    fig.suptitle(f"{title(r)}: stopped at {outcome}")
    fig.tight_layout()
    return fig
