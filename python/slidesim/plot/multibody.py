"""The plots of the multibody scenarios (pendulum, fourbar, sled, contact),
shared by the pendulum, fourbar, sled and contact plots:
the coordinates over time (angles in degrees), the body paths, the contact
forces and speeds, the energy."""
import numpy as np

from .common import DEGREES, draw_surface, equal_axes_3d, title


def coordinates(ax, r, group):
    """Every generalized coordinate over time, angles in degrees."""
    t = r[group + "/time"].values
    for name in sorted(r.file[group + "/coordinates"]):
        q = r[f"{group}/coordinates/{name}/value"]
        scale, unit = (DEGREES, "deg") if q.units == "rad" else (1.0, q.units)
        ax.plot(t, q.values * scale, label=f"{name} [{unit}]")
    ax.set_xlabel("time [s]")
    ax.set_title("coordinates")
    ax.grid(True)
    ax.legend(fontsize=8)


def energy(ax, r, group):
    """Kinetic, potential and total energy change; the closure residual."""
    t = r[group + "/time"].values
    kinetic, potential = r[group + "/kinetic_energy"].values, r[group + "/potential_energy"].values
    ax.plot(t, kinetic, label="kinetic")
    ax.plot(t, potential - potential[0], label="potential − start")
    ax.plot(t, kinetic + potential - kinetic[0] - potential[0], "k-", label="total − start")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy [J]")
    ax.set_title("energy")
    ax.grid(True)
    ax.legend(fontsize=8)


def body_paths(ax, r, group, plane=None):
    """The paths of the body frames' origins: in 3-D, or projected on a
    coordinate plane ('xz', 'xy'); returns the points drawn."""
    drawn = []
    for name in sorted(r.file[group + "/bodies"]):
        p = r[f"{group}/bodies/{name}/position"].values
        if np.ptp(p, axis=0).max() < 1e-12:
            continue   # a body whose frame origin stays put (a hinge)
        drawn.append(p)
        if plane is None:
            ax.plot(*p.T, lw=1, label=name)
        else:
            i, j = ("xyz".index(plane[0]), "xyz".index(plane[1]))
            ax.plot(p[:, i], p[:, j], lw=1, label=name)
    return np.vstack(drawn) if drawn else np.zeros((0, 3))


def contact_forces(ax, r, group, contacts, speeds):
    """The normal force of each contact in `contacts` [(name, line style)] and,
    on a second axis, the speed of the contact points in `speeds` (dotted)."""
    t = r[group + "/time"].values
    for name, style in contacts:
        ax.plot(t, r[f"{group}/contacts/{name}/normal_force"].values, style, label=f"{name} normal force")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("force [N]")
    ax.grid(True)
    ax2 = ax.twinx()
    for name in speeds:
        ax2.plot(t, np.linalg.norm(r[f"{group}/contacts/{name}/velocity"].values, axis=1), ":",
                 label=f"{name} speed")
    ax2.set_ylabel("speed [m/s]")
    ax.legend(loc="upper left", fontsize=8)
    ax2.legend(loc="upper right", fontsize=8)
    ax.set_title("contact forces and speeds")


def suptitle(fig, r):
    fig.suptitle(title(r))
