"""What the plots share: the scale of angles, 3-D axes at one scale, the
slide's surface, the title."""

DEGREES = 180 / 3.141592653589793


def equal_axes_3d(ax, points):
    """The same scale on x, y and z, so curves and sections look as they are."""
    import numpy as np
    lo, hi = points.min(axis=0), points.max(axis=0)
    mid, half = (lo + hi) / 2, max((hi - lo).max() / 2, 1e-9)
    ax.set_xlim(mid[0] - half, mid[0] + half)
    ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    return np


def draw_surface(ax, result, alpha=0.35, u_range=None):
    """The surface grid of the run (/geometry/surface), if the file has one,
    optionally only where u_range[0] <= u <= u_range[1]; returns its points
    (k, 3) for the axis limits."""
    import numpy as np
    if "/geometry/surface/x" not in result:
        return np.zeros((0, 3))
    x, y, z = (result["/geometry/surface/" + c].values for c in "xyz")
    if u_range is not None:
        u = result["/geometry/surface/u"].values
        rows = (u >= u_range[0]) & (u <= u_range[1])
        if rows.sum() >= 2:
            x, y, z = x[rows], y[rows], z[rows]
    ax.plot_surface(x, y, z, color="lightsteelblue", alpha=alpha, linewidth=0.2, edgecolor="slategray",
                    rstride=max(1, x.shape[0] // 100), cstride=max(1, x.shape[1] // 24))
    return np.column_stack([x.ravel(), y.ravel(), z.ravel()])


def title(result):
    """The file's title, scenario and how the run ended."""
    text = result.attrs.get("title") or result.scenario
    status = result.status
    if status != "complete":
        text += f" (INCOMPLETE: {result.status_message})"
    return text
