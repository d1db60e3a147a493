"""Draws the tilt theta(t) of the spinning egg from contact result files
(scenario `contact`, inputs/contact/egg*.nml) next to the Moffatt-Shimomura
curve tan(theta) = tan(theta_0) exp(-mu q (t - t_0)), thesis (3.88) with the
corrected sign of q = 5 g (b^2 - a^2) / (2 (a^2 + b^2)) (METHOD-PART2 A.4.2).

theta is the angle between the egg's symmetry axis (the body axis whose
semi-axis differs from the other two: body y in inputs/contact/egg.nml,
a = c; body z for an egg described with a = b) and the vertical. mu, the
semi-axes and g are read from the input stored in each file; an ellipsoid
without two equal semi-axes is refused (Moffatt-Shimomura is for spheroids). The MS curve of each run passes through the
simulated theta = 45 degrees; the legend gives the fitted slope of
ln tan(theta) over 10..60 degrees as a fraction of -mu q.

    slidesim-plot --kind egg RESULT.h5 [RESULT.h5 ...] [-o PICTURE] [--show]
"""
import re

import numpy as np


SCENARIOS = ("contact",)
SEVERAL = True   # several files, compared


def group_values(text, group):
    """The assignments of every &group in a namelist text (a list of dicts)."""
    found = []
    for body in re.findall(r"&" + group + r"\b(.*?)\n\s*/", text, flags=re.S | re.I):
        values = {}
        body = re.sub(r"!.*", "", body)
        for name, value in re.findall(r"(\w+)\s*=\s*([^=]+?)(?=,?\s*\w+\s*=|$)", body, flags=re.S):
            values[name.lower()] = value.strip().rstrip(",").strip()
        found.append(values)
    return found


def egg_parameters(text):
    mu = None
    for contact in group_values(text, "contact"):
        if "mu" in contact:
            mu = float(contact["mu"])
    a = b = axis = None
    for shape in group_values(text, "shape"):
        if shape.get("kind", "").strip("'\"") == "ellipsoid":
            semi = [float(shape[k]) for k in ("a", "b", "c")]
            # the symmetry axis: the one whose semi-axis differs from the other two
            for i in range(3):
                j, k = (i + 1) % 3, (i + 2) % 3
                if semi[j] == semi[k]:
                    axis, a, b = i, semi[j], semi[i]
                    break
            if axis is None:
                raise SystemExit(f"error: the egg's ellipsoid has semi-axes {semi}: no two are equal, "
                                 "Moffatt-Shimomura's curve needs a spheroid")
    g = 9.80665   # the contact scenario's default (standard gravity)
    for model in group_values(text, "contact_model"):
        if "gravity" in model:
            g = np.linalg.norm([float(x) for x in model["gravity"].split(",")])
    if mu is None or a is None:
        raise SystemExit("the input stored in the file has no friction mu or no ellipsoid")
    return mu, a, b, g, axis


def tilt(f, axis):
    """theta of body axis `axis` (0, 1, 2: x, y, z) against the vertical."""
    rot = f["contact/bodies/egg/rotation"][...]       # rot[i, k, :] = body axis k, world (docs/outputs.md)
    return np.degrees(np.arccos(np.clip(np.abs(rot[:, axis, 2]), 0.0, 1.0)))


def draw(results, plt, args):
    """The figure of the results; args: the command line's."""
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 9), sharex=True)
    for path, r in zip(args.files, results):
        f = r.file
        if "contact/bodies/egg/rotation" not in f:
            raise SystemExit(f"error: {path}: a contact result without a body named 'egg'")
        t = f["contact/time"][...]
        text = r.input_text
        title = re.search(r"title\s*=\s*'([^']*)'", text)
        mu, a, b, g, axis = egg_parameters(text)
        theta = tilt(f, axis)
        q = 5 * g * (b**2 - a**2) / (2 * (a**2 + b**2))
        lt = np.log(np.tan(np.radians(np.maximum(theta, 1e-6))))
        window = (theta > 10) & (theta < 60)
        slope = np.polyfit(t[window], lt[window], 1)[0] if window.sum() > 2 else np.nan
        t45 = t[np.argmax(theta <= 45)]
        ms = np.degrees(np.arctan(np.exp(-mu * q * (t - t45))))
        label = title.group(1) if title else path
        line, = ax1.plot(t, theta, label=f"{label}: slope {slope / (-mu * q):.3f} of -mu q")
        ax1.plot(t, ms, "--", color=line.get_color(), lw=1)
        ax2.plot(t, lt, color=line.get_color())
        ax2.plot(t, -mu * q * (t - t45), "--", color=line.get_color(), lw=1)
    ax1.set_ylabel("tilt of the long axis theta (deg)")
    ax1.set_title("spinning egg: simulation (solid) and Moffatt-Shimomura (3.88) (dashed)")
    ax1.legend(fontsize=8)
    ax1.grid(alpha=0.3)
    ax2.set_ylabel("ln tan theta")
    ax2.set_xlabel("t (s)")
    ax2.set_ylim(-8, 3)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    return fig
