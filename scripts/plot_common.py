"""What every slidesim plot script shares: one command line, one way to open a
result, one way to save.

    plot_X.py RESULT.h5 [-o PICTURE] [--show]

(a script that compares runs takes several RESULT.h5) writes PICTURE (png, pdf or svg; default: the result's name with .png) and,
with --show and a display, also opens a window. Without a display matplotlib
runs headless (Agg). A file of the wrong kind stops with a message saying
what it is and what the script needs (exit status 1).
"""
import argparse
import os
import sys

import matplotlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from slidesim_results import ResultFileError, open_result  # noqa: E402

DEGREES = 180 / 3.141592653589793


def command_line(description, scenarios, several=False):
    """Parses the common arguments; returns (args, result, pyplot), with
    `several` (args, [result, ...], pyplot) for the files args.files."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("files" if several else "file", nargs="+" if several else None,
                        help=f"slidesim result file of scenario {' or '.join(scenarios)}")
    parser.add_argument("-o", "--output", help="picture to write (png, pdf, svg); default: FILE with .png")
    parser.add_argument("--show", action="store_true", help="also open a window (needs a display)")
    args = parser.parse_args()
    if several:
        args.file = args.files[0]
    if not args.output:
        args.output = os.path.splitext(args.file)[0] + ".png"
    if not (args.show and os.environ.get("DISPLAY")):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    try:
        if several:
            return args, [open_result(path, scenarios) for path in args.files], plt
        result = open_result(args.file, scenarios)
    except ResultFileError as error:
        sys.exit(f"error: {error}")
    return args, result, plt


def finish(args, fig, plt):
    """Saves the figure and, with --show and a display, shows it."""
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")
    if args.show and os.environ.get("DISPLAY"):
        plt.show()


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
