"""Plots a contact result (scenario contact): the paths of the bodies and of
the contact points in 3-D, the bodies' angular velocities (a spin's angle
grows without bound, its rate tells more), the contacts' normal forces and sliding speeds, and the energy. (For the spinning
egg against Moffatt-Shimomura see slidesim-plot --kind egg.)

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

from .common import equal_axes_3d
from .multibody import body_paths, contact_forces, energy, suptitle

SCENARIOS = ("contact",)


def draw(r, plt, args):
    """The figure of a result; args: the command line's."""
    g = "/contact"
    t = r[g + "/time"].values
    contacts = sorted(r.file[g + "/contacts"]) if g + "/contacts" in r else []
    fig = plt.figure(figsize=(15, 9))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    drawn = [body_paths(ax, r, g)]
    for name in contacts:
        p = r[f"{g}/contacts/{name}/position"].values
        ax.plot(*p.T, "--", lw=0.8, label=f"contact {name}")
        drawn.append(p)
    ax.legend(loc="upper left", fontsize=8)
    equal_axes_3d(ax, np.vstack(drawn))
    ax.set_title("paths of the bodies (solid) and contact points (dashed)")
    ax = fig.add_subplot(3, 2, 2)
    bodies = sorted(r.file[g + "/bodies"])
    for name in bodies:
        w = r[f"{g}/bodies/{name}/angular_velocity"].values
        if len(bodies) == 1:   # one body: its components; several: their magnitudes
            for k, axis in enumerate("xyz"):
                ax.plot(t, w[:, k], lw=1, label=f"{name} ω{axis}")
        else:
            ax.plot(t, np.linalg.norm(w, axis=1), lw=1, label=f"{name} |ω|")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("angular velocity [rad/s]")
    ax.set_title("angular velocities (world axes)" if len(bodies) == 1 else "angular speeds")
    ax.grid(True)
    ax.legend(fontsize=8)
    contact_forces(fig.add_subplot(3, 2, 4), r, g, [(name, "-") for name in contacts], contacts)
    energy(fig.add_subplot(3, 2, 6), r, g)
    suptitle(fig, r)
    fig.tight_layout()
    return fig
