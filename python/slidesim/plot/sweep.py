"""The envelope of a sweep (docs/sweep.md): per ride the highest felt
acceleration (magnitude and normal), the top speed and the largest tipping
lever arm against the rider mass (or another swept variable), coloured by
flow rate, marked by body table, with the upper envelope (the largest value
at each x) and the user's limits; failed rides as red crosses along the
bottom.

    slidesim-plot RESULT.h5 [--x mass] [-o PICTURE] [--show]
"""
import h5py
import numpy as np

SCENARIOS = ("sweep",)
SWEPT = ("mass", "height", "mu", "u0", "v0", "heading0_deg", "speed0", "flow_rate", "f1", "f2", "f3")
PANELS = (  # dataset, label, the limit's quantity, absolute value
    ("felt_magnitude_max", "highest felt acceleration |a - g|/|g| (g)", None, False),
    ("felt_normal_max", "highest felt normal acceleration (g)", "acceleration_normal", False),
    ("top_speed", "top speed (m/s)", "speed", False),
    ("lever_arm_max", "largest tipping lever arm |l| (m)", "lever_arm", True),
)


def read(f):
    g = f["/sweep"]
    data = {name: g[name][()] for name in g if isinstance(g[name], h5py.Dataset)}
    units = {name: g[name].attrs.get("units", "") for name in g if isinstance(g[name], h5py.Dataset)}
    limits = {}
    if "limits" in g:
        for key in g["limits"]:
            lim = g["limits"][key]
            q = lim["quantity"].asstr()[()]
            limits[q] = (lim["minimum"][()] if "minimum" in lim else None,
                         lim["maximum"][()] if "maximum" in lim else None)
    title = f.attrs.get("title", "")
    return data, units, limits, title


def draw(result, plt, args):
    """The figure of a result; args: the command line's (args.x)."""
    if args.x not in SWEPT:
        raise SystemExit(f"error: --x {args.x}: not a swept variable; one of {', '.join(SWEPT)}")
    data, units, limits, title = read(result.file)
    x = data[args.x]
    status = data["status"]
    ran = status != 3
    failed = ~ran
    flows = np.unique(data["flow_rate"])
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, max(len(flows), 1)))
    markers = {1: ("o", "male"), 2: ("^", "female")}

    fig, axes = plt.subplots(2, 2, figsize=(11, 8), sharex=True)
    for ax, (name, label, quantity, absolute) in zip(axes.flat, PANELS):
        y = np.abs(data[name]) if absolute else data[name]
        for k, q in enumerate(flows):
            for sex, (marker, word) in markers.items():
                sel = ran & (data["flow_rate"] == q) & (data["sex"] == sex)
                if sel.any():
                    ax.scatter(x[sel], y[sel], color=colours[k], marker=marker, s=28, alpha=0.85,
                               label=f"{q * 1000:g} l/s, {word}")
        if ran.any():   # the upper envelope: the largest value at each x
            xs = np.unique(x[ran])
            top = [y[ran & (x == v)].max() for v in xs]
            ax.plot(xs, top, color="black", lw=1.2, label="envelope (largest)")
        if quantity in limits:
            low, high = limits[quantity]
            for bound, word in ((high, "limit"), (low, "lower limit")):
                if bound is not None:
                    ax.axhline(bound, color="red", ls="--", lw=1, label=f"{word} {bound:g}")
        if failed.any():   # below every ride that ran
            low, high = (y[ran].min(), y[ran].max()) if ran.any() else (0.0, 1.0)
            bottom = low - 0.1 * ((high - low) or abs(high) or 1.0)
            ax.scatter(x[failed], np.full(failed.sum(), bottom), color="red", marker="x", s=40,
                       label=f"failed ({failed.sum()})")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel(f"{args.x} ({units.get(args.x, '')})")
    handles, labels = axes.flat[0].get_legend_handles_labels()
    for ax in axes.flat[1:]:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=min(len(labels), 4), fontsize=8, frameon=False)
    n = len(status)
    fig.suptitle(f"{title}: {n} rides, {int((status == 1).sum())} complete, {int((status == 2).sum())} stopped, "
                 f"{int(failed.sum())} failed", fontsize=11)
    fig.tight_layout(rect=(0, 0.08, 1, 0.96))
    return fig
