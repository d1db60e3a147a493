"""The plots of the multibody scenarios (pendulum, fourbar, sled, contact),
shared by the pendulum, fourbar, sled and contact plots:
the coordinates over time (angles in degrees), the body paths, the contact
forces and speeds, the energy."""
import numpy as np

from .common import DEGREES, draw_surface, equal_axes_3d, title


def coordinates(ax, r, group):
    """Every generalized coordinate over time (angles in degrees), one y axis
    per unit: the coordinates of the first unit (by name) on `ax`, each
    further unit dashed on its own axis at the right (a sled's u in m beside
    its angle phi in deg), each axis labelled with its coordinates and unit.
    Returns the axes, `ax` first."""
    import matplotlib
    t = r[group + "/time"].values
    by_unit = {}
    for name in sorted(r.file[group + "/coordinates"]):
        q = r[f"{group}/coordinates/{name}/value"]
        scale, unit = (DEGREES, "deg") if q.units == "rad" else (1.0, q.units or "1")
        by_unit.setdefault(unit, []).append((name, q.values * scale))
    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    axes, lines = [ax], []
    for k, (unit, curves) in enumerate(by_unit.items()):
        if k > 0:
            axes.append(ax.twinx())
            if k > 1:
                axes[-1].spines["right"].set_position(("axes", 1 + 0.15 * (k - 1)))
        for name, values in curves:   # ax's own colour cycle goes on (a caller may add lines to it)
            style = {"color": colors[len(lines) % len(colors)], "ls": "--"} if k > 0 else {}
            lines += axes[-1].plot(t, values, label=f"{name} [{unit}]", **style)
        axes[-1].set_ylabel(f"{', '.join(name for name, _ in curves)} [{unit}]")
    ax.set_xlabel("time [s]")
    ax.set_title("coordinates" + (" (dashed: right axis)" if len(axes) > 1 else ""))
    ax.grid(True)
    ax.legend(lines, [line.get_label() for line in lines], fontsize=8)
    return axes


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
