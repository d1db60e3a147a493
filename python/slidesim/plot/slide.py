"""Plots a slide (scenario geometry): the surface in 3-D with the centerline
and its frames; for tubes and slides also the plan view coloured by the
turning curvature, the elevation profile and the curvature chi over arc
length split into its turning part (positive: turning left, seen from above)
and its vertical part (positive: concave up, as a drop's curve-out); where
the wall's distance from the centerline changes along the slide (a funnel,
a free-form patch, blended sections) a map of it over arc length and v.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import textwrap

import numpy as np

from .common import draw_surface, equal_axes_3d, title

SCENARIOS = ("geometry",)
SURFACE_TITLE_WIDTH = 70   # characters a line of the 3-D panel's title holds


def curvature_parts(points, s, chi):
    """chi split into its turning part (along the horizontal normal: + to the
    left, counter-clockwise seen from above) and its vertical part (along the
    normal in the vertical plane of the tangent: + concave up), by the
    direction of the curvature vector from differences of the points."""
    t = np.gradient(points, s, axis=0)
    k = np.gradient(t, s, axis=0)
    t /= np.linalg.norm(t, axis=1)[:, None]
    k -= np.sum(k * t, axis=1)[:, None] * t
    k /= np.maximum(np.linalg.norm(k, axis=1), 1e-300)[:, None]
    left = np.stack([-t[:, 1], t[:, 0], np.zeros(len(t))], axis=1)
    left /= np.maximum(np.linalg.norm(left, axis=1), 1e-300)[:, None]
    up = np.cross(t, left)
    return chi * np.sum(k * left, axis=1), chi * np.sum(k * up, axis=1)


def wall_distance(r, points, s):
    """The wall's distance from the centerline on the surface grid, with the
    arc length of the grid's u (the centerline's points taken at the grid's
    u by interpolation where the two grids differ)."""
    u = r["/geometry/surface/u"].values
    c_u = r["/geometry/centerline/u"].values
    wall = np.stack([r["/geometry/surface/" + a].values for a in "xyz"], axis=-1)
    centre = np.stack([np.interp(u, c_u, points[:, k]) for k in range(3)], axis=-1)
    return np.interp(u, c_u, s), np.linalg.norm(wall - centre[:, None, :], axis=-1)


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
    tube = "/geometry/centerline/points" in r
    fig = plt.figure(figsize=(14, 8) if tube else (8, 7))
    ax = fig.add_subplot(1, 2 if tube else 1, 1, projection="3d")
    pts = draw_surface(ax, r, alpha=0.5)
    if tube:
        points = r["/geometry/centerline/points"].values
        s = r["/geometry/centerline/arc_length"].values
        chi = r["/geometry/centerline/chi"].values
        ax.plot(*points.T, "k-", lw=1.2, label="centerline")
        step = max(1, len(points) // 25)
        scale = 0.05 * np.ptp(points, axis=0).max()
        for axis, colour in zip("xyz", "rgb"):
            d = r["/geometry/centerline/frame_" + axis].values[::step] * scale
            p = points[::step]
            ax.quiver(p[:, 0], p[:, 1], p[:, 2], d[:, 0], d[:, 1], d[:, 2], color=colour, lw=0.8)
        ax.legend(loc="upper left")
    equal_axes_3d(ax, pts)
    # the surface's description in lines that fit the 3-D panel (half the
    # figure: a slide of six elements ran off its left edge in one line)
    surface = "\n".join(textwrap.wrap(r.attrs.get("surface", "surface"), SURFACE_TITLE_WIDTH))
    ax.set_title(f"{surface}\n(frames: x red, y green, z blue)")
    if tube:
        turning, vertical = curvature_parts(points, s, chi)
        s_grid, distance = wall_distance(r, points, s)
        varies = np.ptp(distance, axis=0).max() > 1e-3
        rows = 3 if varies else 2
        plan = fig.add_subplot(rows, 4, 3)
        limit = max(np.abs(turning).max(), 1e-12)
        sc = plan.scatter(points[:, 0], points[:, 1], c=turning, s=4, cmap="coolwarm", vmin=-limit, vmax=limit)
        plan.plot(points[0, 0], points[0, 1], "go", label="start")
        plan.set_aspect("equal")
        plan.set_xlabel("x [m]")
        plan.set_ylabel("y [m]")
        plan.set_title("plan view")
        plan.legend(fontsize=8)
        fig.colorbar(sc, ax=plan, label="turning curvature [1/m]")
        profile = fig.add_subplot(rows, 4, 4)
        profile.plot(s, points[:, 2], "k-")
        profile.set_xlabel("arc length [m]")
        profile.set_ylabel("elevation z [m]")
        profile.set_title(f"elevation profile (drop {points[0, 2] - points[-1, 2]:.2f} m)")
        profile.grid(True)
        if varies:
            wall = fig.add_subplot(rows, 2, 6)
            v = r["/geometry/surface/v"]
            mesh = wall.pcolormesh(s_grid, v.values, distance.T, shading="auto", cmap="viridis")
            fig.colorbar(mesh, ax=wall, label="distance [m]")
            wall.set_xlabel("arc length [m]")
            wall.set_ylabel(f"v [{getattr(v, 'units', '')}]")
            wall.set_title("the wall's distance from the centerline")
        curv = fig.add_subplot(rows, 2, 4)
        curv.plot(s, turning, "b-", label="turning (+ left)")
        curv.plot(s, vertical, "r-", label="vertical (+ concave up)")
        curv.axhline(0, color="gray", lw=0.5)
        curv.set_xlabel("arc length [m]")
        curv.set_ylabel("curvature [1/m]")
        curv.set_title("curvature chi (4.8): its turning and vertical parts")
        curv.legend(fontsize=8)
        curv.grid(True)
    fig.suptitle(title(r))
    fig.tight_layout()
    return fig
