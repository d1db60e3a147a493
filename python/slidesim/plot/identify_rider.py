"""Plots a result file of the rider-friction identification (scenario
`identify_rider`): measured against simulated
- wall angles of the pelvis, heels and back at every station (left; the
  simulated ones at the identified mu_D, lines, the measured ones, markers);
- speeds on every segment (right, with the segments as horizontal bars);
and the identified mu_D with its standard error in the title.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show]
"""
import numpy as np

CONTACTS = ("pelvis", "heels", "back")
COLOURS = ("tab:blue", "tab:orange", "tab:green")
SCENARIOS = ("identify_rider",)


def draw(result, plt, args):
    """The figure of a result; args: the command line's."""
    f = result.file
    g = f["/identify_rider"]
    mu, se = float(g["mu"][()]), float(g["standard_error"][()])
    twin = float(g["twin_mu"][()]) if "twin_mu" in g else None
    stations = "stations" in g
    if stations:
        s = g["stations/arc_length"][:]
        measured = g["stations/measured_angle"][:]
        simulated = g["stations/simulated_angle"][:]
    segments = "segments" in g
    if segments:
        a, b = g["segments/start"][:], g["segments/end"][:]
        w_measured = g["segments/measured_speed"][:]
        w_simulated = g["segments/simulated_speed"][:]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    title = f"identified mu_D = {mu:.6g} ± {se:.2g} (1 standard error)"
    if twin is not None:
        title += f"; twin experiment with mu_D = {twin:.6g}"
    fig.suptitle(title)
    if stations:
        for k, name in enumerate(CONTACTS):
            left.plot(s, np.degrees(simulated[:, k]), "-", color=COLOURS[k], label=f"{name}, simulated")
            left.plot(s, np.degrees(measured[:, k]), "o", color=COLOURS[k], mfc="none", label=f"{name}, measured")
        left.set_xlabel("station: centerline arc length (m)")
        left.set_ylabel("wall angle (deg, 0 = bottom)")
        left.set_title("where the pelvis crosses each station")
        left.legend(fontsize=8)
        left.grid(alpha=0.3)
    if segments:
        for k in range(len(a)):
            right.plot([a[k], b[k]], [w_measured[k]] * 2, "-", color="k", lw=3, label="measured" if k == 0 else None)
            right.plot([a[k], b[k]], [w_simulated[k]] * 2, "--", color="tab:red", lw=2,
                       label="simulated" if k == 0 else None)
        right.set_xlabel("centerline arc length (m)")
        right.set_ylabel("speed: segment length / passage time (m/s)")
        right.set_title("segment speeds of the pelvis")
        right.legend(fontsize=8)
        right.grid(alpha=0.3)
    fig.tight_layout()
    return fig
