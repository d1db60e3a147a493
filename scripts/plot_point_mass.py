#!/usr/bin/python3
"""Plots a point_mass result file: the path in 3-D, speed and normal force over
time, and the energy balance (energy - friction work, which must stay constant).

usage: scripts/plot_point_mass.py result.h5 [picture.png]
Without a picture name the figure is written next to the result file as .png.
"""
import sys

import h5py
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
        g = f["/point_mass"]
        t = g["time"][:]
        xyz = g["position"][:]
        speed = g["speed"][:]
        normal = g["normal_force"][:]
        balance = g["energy"][:] - g["friction_work"][:]
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)
    fig = plt.figure(figsize=(12, 8))
    ax = fig.add_subplot(2, 2, 1, projection="3d")
    ax.plot(xyz[:, 0], xyz[:, 1], xyz[:, 2])
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.set_title(f"path ({status})")
    ax = fig.add_subplot(2, 2, 2)
    ax.plot(t, speed)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("speed (m/s)")
    ax = fig.add_subplot(2, 2, 3)
    ax.plot(t, normal)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("normal force (N)")
    ax = fig.add_subplot(2, 2, 4)
    ax.plot(t, balance - balance[0])
    ax.set_xlabel("t (s)")
    ax.set_ylabel("energy - friction work - initial (J)")
    fig.tight_layout()
    fig.savefig(picture, dpi=90)
    print(picture)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
