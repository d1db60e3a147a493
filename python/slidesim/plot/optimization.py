"""Plots a result file of the geometry optimisation (scenario `optimize`):
- the centerline seen from above and from the side, start and optimum, with
  the design points;
- the acceleration of every ride over time, start (dashed) and optimum;
- the tipping lever arm of every ride over time with the limit (a ride whose
  body lifts off has no lever arm there: the curve breaks);
- the section angle of every ride (0 = the bottom of the tube, positive to the
  +v side) over time.

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
        c0 = np.asarray(g["centerline_start"][:])
        p0 = np.asarray(g["points_start"][:])
        before = rides(g["before"])
        optimized = "x" in g
        if optimized:
            c1 = np.asarray(g["centerline"][:])
            p1 = np.asarray(g["points"][:])
            after = rides(g["after"])
        title = result_title(r)

    fig, ax = plt.subplots(2, 3, figsize=(16, 9))
    ax[0, 0].plot(c0[:, 0], c0[:, 1], "k--", label="start")
    ax[0, 0].plot(p0[:, 0], p0[:, 1], "ko", ms=4)
    ax[0, 1].plot(np.r_[0, np.cumsum(np.linalg.norm(np.diff(c0, axis=0), axis=1))], c0[:, 2], "k--", label="start")
    if optimized:
        ax[0, 0].plot(c1[:, 0], c1[:, 1], "C3", label="optimum")
        ax[0, 0].plot(p1[:, 0], p1[:, 1], "C3s", ms=4)
        ax[0, 1].plot(np.r_[0, np.cumsum(np.linalg.norm(np.diff(c1, axis=0), axis=1))], c1[:, 2], "C3",
                      label="optimum")
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
            ax[0, 2].plot(t, a, color=colors[k], label=f"{angles[k]:+.0f} deg")
            ax[1, 0].plot(t, lever, color=colors[k])
            ax[1, 1].plot(t, wall, color=colors[k])
    ax[0, 2].set(xlabel="time (s)", ylabel="acceleration (m/s^2)",
                 title="acceleration (dashed: start, solid: optimum)")
    ax[0, 2].legend(title="start angle", fontsize=8)
    for y in (limit, -limit):
        ax[1, 0].axhline(y, color="r", lw=1)
    ax[1, 0].set(xlabel="time (s)", ylabel="lever arm (m)", title="tipping lever arm (red: limit)")
    ax[1, 0].set_ylim(-1, 1)
    ax[1, 1].set(xlabel="time (s)", ylabel="angle from the bottom (deg)", title="position on the wall")

    # the maxima per ride
    x = np.arange(len(before))
    ax[1, 2].bar(x - 0.2, [np.max(a) for _, a, _, _ in before], 0.4, color="0.6", label="start")
    if optimized:
        ax[1, 2].bar(x + 0.2, [np.max(a) for _, a, _, _ in after], 0.4, color="C3", label="optimum")
    ax[1, 2].set_xticks(x, [f"{a:+.0f}" for a in angles])
    ax[1, 2].set(xlabel="start angle (deg)", ylabel="largest acceleration (m/s^2)", title="largest acceleration")
    ax[1, 2].legend()
    fig.suptitle(f"slidesim optimize: {title}")
    fig.tight_layout()
    return fig
