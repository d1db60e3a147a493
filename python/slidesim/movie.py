"""A film of a ride (a `ride` result file): the slide and its water from
above and behind with the rider on it, a close-up that follows the rider
(legs and trunk drawn as thick bars from the pelvis to the heels and to the
back contact, the water band beneath), and beside them the rider's speed
and felt accelerations over time with the current moment marked.

    python3 -m slidesim.movie RIDE.h5 [-o FILM] [--frames N] [--fps F]
    slidesim-plot RIDE.h5 --movie FILM
    from slidesim.movie import make_movie; make_movie('ride.h5', 'ride.mp4')

FILM .mp4 is written with ffmpeg (Debian's ffmpeg package; test and viewer
extra of scripts/install-dependencies.sh); without ffmpeg, or for a .gif,
a GIF through matplotlib's Pillow writer (a FILM ending in .mp4 then
becomes FILM with .gif, and the message says so). The frames are evenly
spaced in time over the ride (default: fps per second of the ride, at most
600); each shows the sample nearest its time. Exit status 0 done, 1 the
file is not a ride result or a module is missing.
"""
import argparse
import os
import shutil
import sys

from ._needs import MissingModule, need

CLOSE_UP = 1.6        # m: half the size of the close-up's box around the pelvis
MAX_FRAMES = 600


class NotARide(ValueError):
    """The file is not a ride result with a rider's series."""


def read_ride(path):
    """The arrays of a ride result the film needs (numpy arrays)."""
    import h5py
    import numpy as np
    with h5py.File(path, "r") as f:
        scenario = f.attrs.get("scenario", b"")
        scenario = scenario.decode() if isinstance(scenario, bytes) else str(scenario)
        if scenario != "ride" or "/rider/time" not in f:
            raise NotARide(f"{path}: a '{scenario}' result, not a ride with a rider's series (scenario ride)")
        d = {name: f["/rider/" + name][()] for name in ("time", "speed", "acceleration_g")}
        for contact in ("pelvis", "heels", "back"):
            d[contact] = f[f"/rider/{contact}/position"][()]
        d["surface"] = np.stack([f["/geometry/surface/" + c][()] for c in "xyz"], axis=-1)
        d["left"] = f["/water/left_point"][()] if "/water/left_point" in f else None
        d["right"] = f["/water/right_point"][()] if "/water/right_point" in f else None
        title = f.attrs.get("title", b"")
        d["title"] = title.decode() if isinstance(title, bytes) else str(title)
    if len(d["time"]) < 2:
        raise NotARide(f"{path}: the ride has {len(d['time'])} sample(s), a film needs two")
    return d


def frame_rows(time, frames):
    """The sample shown in each of `frames` frames evenly spaced in time."""
    import numpy as np
    wanted = np.linspace(time[0], time[-1], frames)
    rows = np.searchsorted(time, wanted)
    rows = np.clip(rows, 0, len(time) - 1)
    before = np.clip(rows - 1, 0, len(time) - 1)
    closer = np.abs(time[before] - wanted) < np.abs(time[rows] - wanted)
    return np.where(closer, before, rows)


def writer_for(out, fps):
    """(matplotlib writer, the file it writes): ffmpeg for .mp4 when it is
    installed, else Pillow's GIF."""
    from matplotlib import animation
    root, extension = os.path.splitext(out)
    if extension.lower() != ".gif" and shutil.which("ffmpeg") and animation.writers.is_available("ffmpeg"):
        return animation.FFMpegWriter(fps=fps, codec="libx264", extra_args=["-pix_fmt", "yuv420p"]), out
    if extension.lower() != ".gif":
        out = root + ".gif"
        print(f"slidesim.movie: ffmpeg not found: writing a GIF, {out}", file=sys.stderr)
    return animation.PillowWriter(fps=fps), out


def _box(ax, centre, half):
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)


def make_movie(path, out, frames=None, fps=20, dpi=100):
    """Writes the film of the ride in `path` to `out`; returns the file
    written (a .gif when ffmpeg is missing) and the number of frames."""
    import matplotlib
    if matplotlib.get_backend().lower() not in ("agg", "pdf", "svg"):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    d = read_ride(path)
    time = d["time"]
    if frames is None:
        frames = int(min(MAX_FRAMES, max(2, round((time[-1] - time[0]) * fps) + 1)))
    if frames < 1:
        raise ValueError(f"frames must be at least 1, not {frames}")
    rows = frame_rows(time, frames)
    surface = d["surface"]
    writer, out = writer_for(out, fps)

    fig = plt.figure(figsize=(12.8, 7.2))
    fig.suptitle(d["title"] or os.path.basename(path))
    overview = fig.add_subplot(2, 2, 1, projection="3d")
    close = fig.add_subplot(2, 2, 2, projection="3d", computed_zorder=False)
    speed_ax = fig.add_subplot(2, 2, 3)
    felt_ax = fig.add_subplot(2, 2, 4)

    # the whole slide, every few rows and columns, the water's edges, the pelvis's path
    step_u = max(1, surface.shape[0] // 60)
    step_v = max(1, surface.shape[1] // 8)
    overview.plot_wireframe(surface[..., 0], surface[..., 1], surface[..., 2], rstride=step_u, cstride=step_v,
                            color="0.7", linewidth=0.4)
    for edge in (d["left"], d["right"]):
        if edge is not None:
            overview.plot(edge[:, 0], edge[:, 1], edge[:, 2], color="tab:blue", linewidth=0.8)
    overview.plot(d["pelvis"][:, 0], d["pelvis"][:, 1], d["pelvis"][:, 2], color="tab:red", linewidth=0.5)
    marker, = overview.plot([], [], [], "o", color="tab:red", markersize=7)
    overview.set_title("the slide and the water", fontsize=10)
    overview.set_xlabel("x (m)"); overview.set_ylabel("y (m)"); overview.set_zlabel("z (m)")
    span = surface.reshape(-1, 3)
    middle = 0.5 * (span.max(axis=0) + span.min(axis=0))
    _box(overview, middle, 0.5 * float((span.max(axis=0) - span.min(axis=0)).max()))

    speed_ax.plot(time, d["speed"], color="tab:red")
    speed_ax.set_xlabel("time (s)"); speed_ax.set_ylabel("speed (m/s)")
    speed_ax.grid(True, alpha=0.3)
    for k, name in enumerate(("longitudinal", "lateral", "normal")):
        felt_ax.plot(time, d["acceleration_g"][:, k], label=name)
    felt_ax.set_xlabel("time (s)"); felt_ax.set_ylabel("felt acceleration (g)")
    felt_ax.legend(loc="upper left", fontsize=8); felt_ax.grid(True, alpha=0.3)
    cursors = [ax.axvline(time[0], color="k", linewidth=1) for ax in (speed_ax, felt_ax)]
    label = speed_ax.text(0.02, 0.92, "", transform=speed_ax.transAxes)

    centres = surface.mean(axis=1)          # a point of each row of the surface
    water = None
    if d["left"] is not None and d["right"] is not None:
        water = 0.5 * (d["left"] + d["right"])

    def draw(frame):
        i = rows[frame]
        pelvis, heels, back = d["pelvis"][i], d["heels"][i], d["back"][i]
        marker.set_data_3d([pelvis[0]], [pelvis[1]], [pelvis[2]])
        close.cla()
        # the rows of the surface and the water within the box (3-D axes do not clip)
        near = np.nonzero(np.linalg.norm(centres - pelvis, axis=1) < CLOSE_UP)[0]
        if near.size >= 2:
            patch = surface[near]
            close.plot_wireframe(patch[..., 0], patch[..., 1], patch[..., 2], rstride=1,
                                 cstride=max(1, surface.shape[1] // 24), color="0.6", linewidth=0.4)
        if water is not None:
            band = np.nonzero(np.linalg.norm(water - pelvis, axis=1) < CLOSE_UP)[0]
            if band.size >= 2:
                left, right = d["left"][band], d["right"][band]
                close.plot_surface(np.stack([left[:, 0], right[:, 0]]), np.stack([left[:, 1], right[:, 1]]),
                                   np.stack([left[:, 2], right[:, 2]]), color="tab:blue", alpha=0.6,
                                   linewidth=0)
        for end, colour in ((heels, "tab:green"), (back, "tab:purple")):
            close.plot([pelvis[0], end[0]], [pelvis[1], end[1]], [pelvis[2], end[2]], color=colour,
                       linewidth=7, solid_capstyle="round")
        close.plot([pelvis[0]], [pelvis[1]], [pelvis[2]], "o", color="tab:red", markersize=12)
        _box(close, pelvis, CLOSE_UP)
        # seen from behind and above the rider (who slides feet first)
        ahead = heels - pelvis
        close.view_init(elev=55, azim=float(np.degrees(np.arctan2(-ahead[1], -ahead[0]))))
        close.set_title("the rider (legs green, trunk purple)", fontsize=10)
        close.set_xlabel("x (m)"); close.set_ylabel("y (m)"); close.set_zlabel("z (m)")
        for cursor in cursors:
            cursor.set_xdata([time[i], time[i]])
        label.set_text(f"t = {time[i]:.2f} s, {d['speed'][i]:.2f} m/s")
        return []

    folder = os.path.dirname(os.path.abspath(out))
    if not os.path.isdir(folder):
        raise FileNotFoundError(f"{out}: the folder {folder} does not exist")
    # written under a temporary name and renamed when complete: no half film
    temporary = os.path.join(folder, f".{os.path.basename(out)}.{os.getpid()}.tmp{os.path.splitext(out)[1]}")
    try:
        with writer.saving(fig, temporary, dpi):
            for frame in range(frames):
                draw(frame)
                writer.grab_frame()
        os.replace(temporary, out)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)
        plt.close(fig)
    return out, frames


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m slidesim.movie", description="A film of a slidesim ride.")
    p.add_argument("file", help="a ride result (.h5)")
    p.add_argument("-o", "--output", help="the film (.mp4 with ffmpeg, else .gif); default: FILE with .mp4")
    p.add_argument("--frames", type=int, help=f"number of frames (default: fps per second of ride, at most "
                                               f"{MAX_FRAMES})")
    p.add_argument("--fps", type=int, default=20, help="frames per second of the film (default 20)")
    args = p.parse_args(argv)
    if args.frames is not None and args.frames < 1:
        p.error(f"--frames must be at least 1, not {args.frames}")
    if args.fps < 1:
        p.error(f"--fps must be at least 1, not {args.fps}")
    try:
        written, n = make_movie(args.file, args.output or os.path.splitext(args.file)[0] + ".mp4",
                                args.frames, args.fps)
    except ModuleNotFoundError as error:
        print(f"error: {need(error)}", file=sys.stderr)
        return 1
    except (MissingModule, NotARide, OSError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    print(f"wrote {written} ({n} frames)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
