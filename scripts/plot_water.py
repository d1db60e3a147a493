#!/usr/bin/python3
"""Plots a water result file (scenario `water`):
- the unrolled slide: the angle v of the water's middle and of its edges over
  the centerline arc length (as thesis fig. 4.11; v = pi/2 is the bottom,
  shown as 0 deg, positive to the left), with the stations marked;
- speed and water height over arc length;
- the water band (between the edges) on the slide in 3-D.

usage: scripts/plot_water.py result.h5 [picture.png]
Without a picture name the figure is written next to the result file as .png.
"""
import math
import sys

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 1
    path = argv[1]
    picture = argv[2] if len(argv) > 2 else path.rsplit(".", 1)[0] + ".png"
    with h5py.File(path, "r") as f:
        g = f["/water"]
        s = g["arc_length"][:]
        v = g["v"][:]
        speed = g["speed"][:]
        height = g["height"][:]
        xyz = np.asarray(g["position"][:])
        # the edges at the samples (edges = .true.), else those of the table rows
        edges = "left_edge_u" in g
        if edges:
            band_s = s
            band_left = g["left_edge_v"][:]
            band_right = g["right_edge_v"][:]
            lp = np.asarray(g["left_point"][:])
            rp = np.asarray(g["right_point"][:])
        else:
            band_s = g["table/arc_length"][:]
            band_left = g["table/v_left"][:]
            band_right = g["table/v_right"][:]
            lp = rp = np.zeros((0, 3))
        stations = None
        if "stations" in g:
            stations = (g["stations/arc_length"][:], g["stations/v_middle"][:], g["stations/reached"][:])
        status = f.attrs.get("status", b"?")
        outcome = g.attrs.get("outcome", b"?")
    status = status.decode() if isinstance(status, bytes) else str(status)
    outcome = outcome.decode() if isinstance(outcome, bytes) else str(outcome)
    # HDF5 stores the Fortran (3 x n) arrays as n x 3
    if xyz.shape[0] == 3 and xyz.shape[1] != 3:
        xyz = xyz.T
        if edges:
            lp, rp = lp.T, rp.T
    deg = 180 / math.pi

    fig = plt.figure(figsize=(13, 9))
    ax1 = fig.add_subplot(2, 2, 1)
    ax1.plot(s, (v - math.pi / 2) * deg, "b-", label="streamline (middle)")
    if len(band_s) > 0:
        ax1.fill_between(band_s, (band_right - math.pi / 2) * deg, (band_left - math.pi / 2) * deg,
                         color="tab:blue", alpha=0.25, label="water band")
    if stations is not None:
        reached = stations[2] == 1
        ax1.plot(stations[0][reached], (stations[1][reached] - math.pi / 2) * deg, "ko",
                 label="stations (middle of the edges)")
    ax1.set_xlabel("centerline arc length (m)")
    ax1.set_ylabel("angle from the bottom (deg, + left)")
    ax1.set_title("unrolled slide (thesis fig. 4.11)")
    ax1.grid(True)
    ax1.legend(fontsize=8)

    ax2 = fig.add_subplot(2, 2, 3)
    ax2.plot(s, speed, "r-")
    ax2.set_xlabel("centerline arc length (m)")
    ax2.set_ylabel("speed (m/s)", color="r")
    ax2.grid(True)
    ax2b = ax2.twinx()
    ax2b.plot(s, height * 1000, "g-")
    ax2b.set_ylabel("water height (mm)", color="g")
    ax2.set_title("speed and height")

    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    ax3.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2], "b-", lw=0.8)
    if edges:
        band_x = np.vstack([rp[:, 0], lp[:, 0]])
        band_y = np.vstack([rp[:, 1], lp[:, 1]])
        band_z = np.vstack([rp[:, 2], lp[:, 2]])
        ax3.plot_surface(band_x, band_y, band_z, color="tab:blue", alpha=0.5, linewidth=0)
        ax3.plot(lp[:, 0], lp[:, 1], lp[:, 2], "c-", lw=0.5)
        ax3.plot(rp[:, 0], rp[:, 1], rp[:, 2], "c-", lw=0.5)
    ax3.set_xlabel("x (m)")
    ax3.set_ylabel("y (m)")
    ax3.set_zlabel("z (m)")
    ax3.set_title("water band on the slide")
    span = max(np.ptp(xyz[:, 0]), np.ptp(xyz[:, 1]), np.ptp(xyz[:, 2]), 1e-9) / 2
    mid = xyz.min(axis=0) + np.ptp(xyz, axis=0) / 2
    ax3.set_xlim(mid[0] - span, mid[0] + span)
    ax3.set_ylim(mid[1] - span, mid[1] + span)
    ax3.set_zlim(mid[2] - span, mid[2] + span)

    fig.suptitle(f"{path}: {status}, stopped at: {outcome}")
    fig.tight_layout()
    fig.savefig(picture, dpi=110)
    print(picture)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
