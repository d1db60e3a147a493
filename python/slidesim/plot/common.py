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


def plot_nearly_constant(ax, t, values, unit):
    """values over t, drawn so that a quantity constant to rounding looks
    constant: matplotlib would stretch a spread of 1e-12 over the whole axis
    and label the ticks against an offset ('1e-13+5.18'), which reads as a
    speed falling from 8 to 4 m/s. A spread below 1e-6 of the values' size
    is drawn on an axis 1e-3 of it either side, the spread said in the
    legend."""
    import numpy as np
    ax.ticklabel_format(axis="y", useOffset=False)
    size = float(np.max(np.abs(values))) if len(values) else 0.0
    spread = float(np.ptp(values)) if len(values) else 0.0
    if size > 0 and spread < 1e-6 * size:
        mid = float(np.mean(values))
        ax.plot(t, values, label=f"constant to {spread:.1e} {unit}")
        ax.set_ylim(mid - 1e-3 * size, mid + 1e-3 * size)
        ax.legend(loc="upper right", fontsize=8)
    else:
        ax.plot(t, values)


def title(result, extra=""):
    """The file's title, scenario and how the run ended (and `extra`), in
    lines that fit a figure (wrapped)."""
    text = result.attrs.get("title") or result.scenario
    status = result.status
    if status != "complete":
        text += f" (INCOMPLETE: {result.status_message})"
    return wrapped(text + extra)


def wrapped(text, width=130, lines=3):
    """text in at most `lines` lines of `width` characters, the rest cut with
    a pointer to where the whole text is (a failure's message can run to
    hundreds of characters and off the picture)."""
    import textwrap
    parts = textwrap.wrap(text, width)
    if len(parts) > lines:
        parts = parts[:lines]
        parts[-1] = parts[-1][:width - 40].rstrip() + " ... (whole text: the file's status_message)"
    return "\n".join(parts)


def flag_spans(x, flags):
    """(start, end) values of x over each run of records whose flag is set
    (a flight: from the take-off record to the first record back on, the
    landing's, or to the last record)."""
    spans, start = [], None
    for i, flag in enumerate(flags):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            spans.append((x[start], x[i]))
            start = None
    if start is not None:
        spans.append((x[start], x[-1]))
    return spans
