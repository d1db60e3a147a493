"""The slidesim package as installed (run with the venv's python, outside the
repository, so `import slidesim` is the installed one): every result of
every input opens with slidesim.open, every group is an xarray Dataset
whose every axis has a coordinate with the values of the file's dimension
scale (the contacts' too, whose scale is in the parent group), every
dataset of the file is in it with its values, units and long_name; the felt
accelerations are marked in the file's g on the pelvis axes; the ride report and the
limits match /evaluation; a file that is not a result is refused naming it.

    check_python_package.py RESULTS_FOLDER TEXT_FILE CMAKELISTS

Prints failures; exit status 1 if any.
"""
import math
import os
import re
import shutil
import sys

import h5py
import numpy as np

import slidesim
from slidesim.results import ResultFileError

failures = []


def fail(text):
    failures.append(text)
    print("FAIL " + text)


def scale_of(d, axis):
    """The dimension scale of axis `axis` of d (d itself if d is a scale)."""
    if h5py.h5ds.is_scale(d.id):
        return d
    dim = d.dims[axis]
    return dim[0] if len(dim) else None


def check_file(path):
    run = slidesim.open(path)
    datasets = run.datasets()
    seen = set()
    with h5py.File(path, "r") as f:
        for group, ds in datasets.items():
            for dim in ds.dims:
                if dim not in ds.coords:
                    fail(f"{path} {group}: dimension {dim} without a coordinate")
            for name, var in list(ds.data_vars.items()) + list(ds.coords.items()):
                if name in ("xyz_name", "felt_axis") or (name not in f[group] and name in ds.coords):
                    continue   # labels of the package, or a scale from another group (checked below)
                d = f[group][name]
                seen.add(d.name)
                values = d.asstr()[()] if h5py.check_string_dtype(d.dtype) else d[()]
                if var.shape != d.shape or not np.array_equal(np.asarray(var.values), np.asarray(values)):
                    fail(f"{path} {d.name}: values differ from the file's")
                units = d.attrs.get("units")
                if units is not None and var.attrs.get("units") != (units.decode() if isinstance(units, bytes) else units):
                    fail(f"{path} {d.name}: units {var.attrs.get('units')!r}, file {units!r}")
                if d.attrs.get("description") and var.attrs.get("long_name") != d.attrs.get("long_name"):
                    fail(f"{path} {d.name}: long_name {var.attrs.get('long_name')!r}, "
                         f"file {d.attrs.get('long_name')!r}")
                for axis, dim in enumerate(var.dims):
                    scale = scale_of(d, axis)
                    if dim == "felt_axis":
                        continue   # the pelvis axes: labels of the package over the file's xyz
                    if scale is None:
                        fail(f"{path} {d.name}: axis {axis} has no scale in the file")
                    elif not np.array_equal(ds.coords[dim].values, scale[()]):
                        fail(f"{path} {d.name}: coordinate {dim} is not the scale {scale.name}")

        def every(name, obj):
            if name.startswith("xdmf/"):
                return   # the XDMF view's copies, not data (docs/outputs.md): no Dataset
            if isinstance(obj, h5py.Dataset) and "/" + name not in seen:
                fail(f"{path}: /{name} in no Dataset")
        f.visititems(every)
    return run, datasets


def check_ride(run, datasets, path):
    rider = datasets["/rider"]
    felt = rider["acceleration_g"]
    if felt.dims != ("time", "felt_axis") or list(felt["felt_axis"].values) != ["longitudinal", "lateral", "normal"]:
        fail(f"{path}: acceleration_g dims {felt.dims}")
    if felt.attrs.get("felt_acceleration_in") != felt.attrs["units"] or felt.attrs["units"] in ("", "1"):
        fail(f"{path}: acceleration_g not marked in its units: {felt.attrs}")
    for contact in ("pelvis", "heels", "back"):
        group = datasets[f"/rider/{contact}"]
        if not np.array_equal(group["time"].values, rider["time"].values):
            fail(f"{path}: /rider/{contact} time is not /rider/time")
    report = run.ride_report()
    with h5py.File(path, "r") as f:
        e = f["/evaluation"]
        for name in ("top_speed", "ride_time", "acceleration_normal_max", "pelvis/normal_force_min"):
            if report.loc[name, "value"] != e[name][()]:
                fail(f"{path}: report {name} {report.loc[name, 'value']} != {e[name][()]}")
        for name, where in (("top_speed", "top_speed_arc_length"), ("heels/wall_angle_max", "heels/wall_arc_length"),
                            ("heels/wall_distance_max", "heels/wall_distance_max_arc_length"),
                            ("acceleration_normal_max", "acceleration_normal_max_arc_length")):
            if report.loc[name, "where_arc_length_m"] != e[where][()]:
                fail(f"{path}: report {name} where {report.loc[name, 'where_arc_length_m']} != {e[where][()]}")
        felt_units = e["acceleration_normal_max"].attrs["units"]
        if report.loc["acceleration_normal_max", "units"] != felt_units or report.loc["top_speed", "units"] != "m/s":
            fail(f"{path}: report units {report['units'].to_dict()}")
        if not math.isnan(report.loc["ride_time", "where_arc_length_m"]):
            fail(f"{path}: ride_time has a place")
        limits = run.limits()
        names = sorted(e["limits"], key=lambda n: int(n.split("_")[0])) if "limits" in e else []
        if list(limits.index) != names:
            fail(f"{path}: limits {list(limits.index)}, file {names}")
        for name in names:
            if limits.loc[name, "verdict"] != e[f"limits/{name}/verdict"].asstr()[()]:
                fail(f"{path}: limit {name} verdict")


def check_older_file(path):
    """A ride file as slidesim wrote it before long_name and the felt units
    (a copy without long_name, felt units '1'): long_name is the description,
    the felt accelerations are marked in 'g'."""
    older = os.path.join(os.getcwd(), "older_ride.h5")
    shutil.copyfile(path, older)
    with h5py.File(older, "r+") as f:
        def strip(name, obj):
            if isinstance(obj, h5py.Dataset) and "long_name" in obj.attrs:
                del obj.attrs["long_name"]
                if "|g|" in obj.attrs.get("description", ""):
                    obj.attrs["units"] = "1"
        f.visititems(strip)
    run = slidesim.open(older)
    felt = run["/rider"]["acceleration_g"]
    if felt.attrs.get("long_name") != felt.attrs.get("description"):
        fail(f"{older}: no long_name from the description: {felt.attrs}")
    if felt.attrs.get("felt_acceleration_in") != "g" or run.ride_report().loc["acceleration_normal_max", "units"] != "g":
        fail(f"{older}: felt accelerations with units '1' not marked in g: {felt.attrs}")
    os.remove(older)


def main(folder, text, cmakelists):
    names = sorted(set(open(os.path.join(folder, "names")).read().split()))
    kinds = set()
    for name in names:
        path = os.path.join(folder, name + ".h5")
        run, datasets = check_file(path)
        kinds.add(run.scenario)
        if run.scenario == "ride":
            check_ride(run, datasets, path)
        elif run.scenario == "contact":
            time = datasets["/contact"]["time"].values
            for group in run.groups:
                if group.startswith(("/contact/contacts/", "/contact/bodies/")) and \
                        not np.array_equal(datasets[group]["time"].values, time):
                    fail(f"{path}: {group} time is not /contact/time")
    print(f"{len(names)} results of {len(kinds)} scenarios opened: {', '.join(sorted(kinds))}")
    for wrong in (text, os.path.join(folder, "no_such_file.h5")):
        try:
            slidesim.open(wrong)
            fail(f"{wrong} opened")
        except ResultFileError as error:
            if os.path.basename(wrong) not in str(error):
                fail(f"{wrong}: the message does not name it: {error}")
    try:
        slidesim.open(os.path.join(folder, "water_demo_slide.h5")).ride_report()
        fail("a water result gave a ride report")
    except ResultFileError as error:
        if "'water' result" not in str(error):
            fail(f"water ride report: {error}")
    check_older_file(os.path.join(folder, "ride_demo_slide.h5"))
    version = re.search(r"project\(slidesim VERSION ([0-9.]+)", open(cmakelists).read()).group(1)
    if slidesim.__version__ != version:
        fail(f"slidesim.__version__ {slidesim.__version__}, CMakeLists.txt {version}")
    if not slidesim.__file__.startswith(sys.prefix):
        fail(f"slidesim imported from {slidesim.__file__}, not from the environment {sys.prefix}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main(*sys.argv[1:])
