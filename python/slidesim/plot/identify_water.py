"""Plots a result file of the water-friction identification (scenario
`identify_water`): measured against simulated
- middle of the flow at every section (left, in degrees from the bottom);
- speeds on every segment (middle, the segments as horizontal bars);
- with a weight sweep (table 4.2): the cost's two parts against the weight
  (right);
and f1, f2, f3 with their standard errors in the title.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np
SCENARIOS = ("identify_water",)


def draw(result, plt, args):
    """The figure of a result; args: the command line's."""
    f = result.file
    g = f["/identify_water"]
    fit, se = g["f"][:], g["standard_error"][:]
    twin = g["twin_f"][:] if "twin_f" in g else None
    sec = {k: g["sections/" + k][:] for k in ("arc_length", "measured_v", "simulated_v")} if "sections" in g else None
    seg = {k: g["segments/" + k][:] for k in ("start", "end", "measured_speed", "simulated_speed")} \
        if "segments" in g else None
    sweep = {k: g["sweep/" + k][:] for k in ("weight", "position_part", "speed_part", "cost")} if "sweep" in g else None
    panels = 3 if sweep else 2
    fig, axes = plt.subplots(1, panels, figsize=(6 * panels, 4.8))
    title = "f1 = {:.6g} ± {:.2g} kg/m, f2 = {:.6g} ± {:.2g} kg, f3 = {:.6g} ± {:.2g} kg m".format(
        fit[0], se[0], fit[1], se[1], fit[2], se[2])
    if twin is not None:
        title += "\ntwin experiment with f = {:.6g}, {:.6g}, {:.6g}".format(*twin)
    fig.suptitle(title, fontsize=10)
    if sec:
        ax = axes[0]
        ax.plot(sec["arc_length"], np.degrees(sec["simulated_v"] - np.pi / 2), "-", color="tab:blue", label="simulated")
        ax.plot(sec["arc_length"], np.degrees(sec["measured_v"] - np.pi / 2), "o", color="k", mfc="none",
                label="measured")
        ax.set_xlabel("section: centerline arc length (m)")
        ax.set_ylabel("middle of the flow (deg from the bottom)")
        ax.set_title("the flow's middle at the sections")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    if seg:
        ax = axes[1]
        for k in range(len(seg["start"])):
            x = [seg["start"][k], seg["end"][k]]
            ax.plot(x, [seg["measured_speed"][k]] * 2, "-", color="k", lw=3, label="measured" if k == 0 else None)
            ax.plot(x, [seg["simulated_speed"][k]] * 2, "--", color="tab:red", lw=2,
                    label="simulated" if k == 0 else None)
        ax.set_xlabel("centerline arc length (m)")
        ax.set_ylabel("speed (m/s)")
        ax.set_title("segment speeds")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    if sweep:
        ax = axes[2]
        ax.plot(sweep["weight"], sweep["position_part"], "o-", label="position part")
        ax.plot(sweep["weight"], sweep["speed_part"], "s-", label="speed part")
        ax.plot(sweep["weight"], sweep["cost"], "k^-", label="cost F1")
        ax.set_xlabel("weight w")
        ax.set_ylabel("rad^2")
        ax.set_title("weight sweep (table 4.2)")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    return fig
