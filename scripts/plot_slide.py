#!/usr/bin/python3
"""Draw a slide (or any surface) in 3-D from the HDF5 file of the `geometry` scenario.

    scripts/plot_slide.py demo_slide_geometry.h5 [-o slide.png] [--frames 25] [--no-show]

Draws the surface grid /geometry/surface/{x,y,z}; for tubes and slides also the
centerline, every n-th frame (x red, y green, z blue) and, in a second panel,
the curvature chi and its derivative chi_u over the arc length.
Needs numpy, h5py and matplotlib (Debian: python3-numpy python3-h5py python3-matplotlib).
"""
import argparse
import sys

import h5py
import os

import numpy as np
import matplotlib

def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", help="result file of `slidesim` with scenario = 'geometry'")
    parser.add_argument("-o", "--output", help="write the figure to this file (png, pdf, svg)")
    parser.add_argument("--frames", type=int, default=25, help="number of frames drawn along the centerline")
    parser.add_argument("--no-show", action="store_true", help="do not open a window")
    args = parser.parse_args()
    if not args.output and not os.environ.get("DISPLAY"):
        # no screen to show it on: write a picture next to the result file
        args.output = os.path.splitext(args.file)[0] + ".png"
    if args.no_show or args.output:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with h5py.File(args.file, "r") as f:
        if "geometry/surface/x" not in f:
            sys.exit(f"{args.file}: no /geometry/surface group (not a geometry result file?)")
        # written as Fortran (n_v, n_u): h5py reads (n_u, n_v)
        x, y, z = (f["geometry/surface/" + c][()] for c in "xyz")
        title = f.attrs.get("surface", "surface")
        if isinstance(title, bytes):
            title = title.decode()
        cl = f["geometry/centerline"] if "geometry/centerline" in f else None
        if cl is not None:
            points = cl["points"][()]          # (n, 3)
            frames = [cl["frame_" + a][()] for a in "xyz"]
            s = cl["arc_length"][()]
            chi = cl["chi"][()]
            chi_u = cl["chi_u"][()]

    fig = plt.figure(figsize=(12, 7) if cl is not None else (8, 7))
    ax = fig.add_subplot(1, 2 if cl is not None else 1, 1, projection="3d")
    ax.plot_surface(x, y, z, color="lightsteelblue", alpha=0.55, linewidth=0.2, edgecolor="slategray",
                    rstride=max(1, x.shape[0] // 120), cstride=max(1, x.shape[1] // 24))
    if cl is not None:
        ax.plot(points[:, 0], points[:, 1], points[:, 2], "k-", lw=1.2, label="centerline")
        step = max(1, len(points) // max(args.frames, 1))
        scale = 0.05 * np.ptp(points, axis=0).max()
        for axis, colour in zip(frames, "rgb"):
            p = points[::step]
            d = axis[::step] * scale
            ax.quiver(p[:, 0], p[:, 1], p[:, 2], d[:, 0], d[:, 1], d[:, 2], color=colour, lw=0.8)
        ax.legend(loc="upper left")
    # equal scales on all axes, so curves and sections look as they are
    lo = np.array([x.min(), y.min(), z.min()])
    hi = np.array([x.max(), y.max(), z.max()])
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(mid[0] - half, mid[0] + half)
    ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_xlabel("x [m]"); ax.set_ylabel("y [m]"); ax.set_zlabel("z [m]")
    ax.set_title(title)

    if cl is not None:
        a1 = fig.add_subplot(2, 2, 2)
        a1.plot(s, chi, "b-")
        a1.set_ylabel("curvature chi [1/m]")
        a1.grid(True)
        a2 = fig.add_subplot(2, 2, 4, sharex=a1)
        a2.plot(s, chi_u, "r-")
        a2.set_xlabel("arc length s [m]")
        a2.set_ylabel("chi_u [1/(m unit of u)]")
        a2.grid(True)
    fig.tight_layout()
    if cl is not None:
        fig.subplots_adjust(wspace=0.35)   # room for the 3-D axis labels
    if args.output:
        fig.savefig(args.output, dpi=150)
        print(f"wrote {args.output}")
    if not args.no_show and not args.output:
        plt.show()


if __name__ == "__main__":
    main()
