"""Every plot of a slidesim result, chosen by the result's scenario.

    slidesim-plot RESULT.h5 [-o PICTURE] [--show] [--kind KIND]
    python -m slidesim.plot RESULT.h5 ...

writes PICTURE (png, pdf or svg; default: the result's name with .png) and,
with --show and a display, also opens a window; without a display matplotlib
runs headless (Agg). --kind picks another plot of the same scenario (egg: the
spinning egg's tilt against Moffatt-Shimomura, from several contact results
compared) or insists on one (a file of another scenario is refused; --kind
water draws the /water group of any result that has one: water, ride, sled).
--movie FILM (when the package has slidesim.movie) films a ride. Exit
status 0 done, 1 the file is not a result of a scenario with a plot (the
message names the file and what it is) or a module is missing (the message
names the package to install).

From Python: `slidesim.plot.figure(path)` returns the matplotlib figure.
"""
import argparse
import importlib
import os
import sys

from .._needs import MissingModule, need

# kind -> (the module in this package, what it draws)
KINDS = {
    "ride": "a ride: the contacts and the water band unrolled, speed, felt g, normal forces, 3-D",
    "water": "the water: the unrolled slide (thesis fig. 4.11), speed and height, the band in 3-D",
    "slide": "a geometry result: the surface with its frames, plan, elevation, curvature",
    "point_mass": "a point mass on a surface: path, speed, energy",
    "pendulum": "a pendulum: angles, paths, energy",
    "fourbar": "a four-bar linkage: angles, energy",
    "sled": "a sled: path on the slide, contact forces, energy",
    "contact": "bodies in point contact: paths, angular velocities, forces, energy",
    "egg": "the spinning egg's tilt against Moffatt-Shimomura (several contact results compared)",
    "optimization": "an optimisation: the slide before and after, every ride's accelerations",
    "identify_rider": "the rider-friction identification: measured against simulated",
    "identify_water": "the water-friction identification: measured against simulated",
    "sweep": "a sweep's envelope: felt g, top speed, lever arm against a swept variable",
}
# scenario (the result's root attribute) -> the plot drawn without --kind
DEFAULT_KIND = {"ride": "ride", "water": "water", "geometry": "slide", "point_mass": "point_mass",
                "pendulum": "pendulum", "fourbar": "fourbar", "sled": "sled", "contact": "contact",
                "optimize": "optimization", "identify_rider": "identify_rider",
                "identify_water": "identify_water", "sweep": "sweep"}


def plot_module(kind):
    """The module that draws `kind` (a key of KINDS)."""
    return importlib.import_module(f".{kind}", __name__)


def _movie_available():
    import importlib.util
    return importlib.util.find_spec("slidesim.movie") is not None


def parser():
    p = argparse.ArgumentParser(
        prog="slidesim-plot", description="Plots a slidesim result (the plot is chosen by its scenario).",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="plots (--kind):\n" + "\n".join(f"  {k:15} {v}" for k, v in KINDS.items()))
    p.add_argument("files", nargs="+", metavar="FILE", help="slidesim result file (.h5); several only with --kind egg")
    p.add_argument("-o", "--output", help="picture to write (png, pdf, svg); default: FILE with .png")
    p.add_argument("--show", action="store_true", help="also open a window (needs a display)")
    p.add_argument("--kind", choices=sorted(KINDS), help="the plot to draw (default: the one of the file's scenario)")
    p.add_argument("--x", default="mass", help="sweep: the swept variable on the x axis (default: mass)")
    if _movie_available():
        p.add_argument("--movie", metavar="FILM", help="a ride: its film (.mp4 with ffmpeg, else .gif; "
                       "slidesim.movie); the picture too only with -o")
        p.add_argument("--movie-frames", type=int, metavar="N",
                       help="the film's number of frames (default: 20 per second of the ride, at most 600)")
    return p


def _choose(result, kind):
    """The kind to draw for an open result, or a ResultFileError."""
    from ..results import ResultFileError
    if kind is None:
        if result.scenario not in DEFAULT_KIND:
            raise ResultFileError(f"{result.path}: a '{result.scenario}' result, which has no plot")
        return DEFAULT_KIND[result.scenario]
    module = plot_module(kind)
    if hasattr(module, "refusal"):   # a plot of a part any of several scenarios may hold (the water's)
        reason = module.refusal(result)
        if reason:
            raise ResultFileError(f"{result.path}: a '{result.scenario}' result, {reason}")
        return kind
    wanted = module.SCENARIOS
    if result.scenario not in wanted:
        raise ResultFileError(f"{result.path}: a '{result.scenario}' result, but this needs a result of "
                              f"{' or '.join(repr(w) for w in wanted)}")
    return kind


def figure(paths, kind=None, plt=None, **options):
    """The matplotlib figure of one result file (or, for kind 'egg', a list of
    them); `options` as the command line's (x='mass' for a sweep)."""
    from ..results import open_result
    if plt is None:
        import matplotlib.pyplot as plt
    paths = [paths] if isinstance(paths, (str, os.PathLike)) else list(paths)
    results = []
    try:
        for path in paths:
            results.append(open_result(os.fspath(path)))
            kind = _choose(results[-1], kind)
        module = plot_module(kind)
        if len(results) > 1 and not getattr(module, "SEVERAL", False):
            raise SystemExit(f"error: the {kind} plot draws one file, not {len(results)}")
        options.setdefault("x", "mass")
        args = argparse.Namespace(file=os.fspath(paths[0]), files=[os.fspath(p) for p in paths], **options)
        return module.draw(results if getattr(module, "SEVERAL", False) else results[0], plt, args)
    finally:
        for result in results:
            result.close()


def main(argv=None):
    """slidesim-plot's command line; returns the exit status."""
    args = parser().parse_args(argv)
    try:
        import matplotlib
        if not (args.show and os.environ.get("DISPLAY")):
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from ..results import ResultFileError
        movie = getattr(args, "movie", None)
        try:
            if args.output or not movie:   # with --movie alone, only the film
                output = args.output or os.path.splitext(args.files[0])[0] + ".png"
                fig = figure(args.files, args.kind, plt, x=args.x)
                fig.savefig(output, dpi=120)
                print(f"wrote {output}")
            if movie:
                from ..movie import make_movie
                written, frames = make_movie(args.files[0], movie, args.movie_frames)
                print(f"wrote {written} ({frames} frames)")
        except (ResultFileError, ValueError, OSError) as error:   # the movie's NotARide is a ValueError
            print(f"error: {error}", file=sys.stderr)
            return 1
        if args.show and os.environ.get("DISPLAY"):
            plt.show()
    except ModuleNotFoundError as error:
        if error.name and error.name.startswith("slidesim"):
            raise
        print(f"error: {need(error)}", file=sys.stderr)
        return 1
    except MissingModule as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    return 0
