"""A slidesim result file as xarray Datasets: one per group, every axis of
every dataset named after its HDF5 dimension scale and carrying the scale's
values as a coordinate, also where the scale lives in a parent group (the
contacts /rider/pelvis, /rider/heels, /rider/back and /contact/bodies/<b>
take /rider/time and /contact/time). Values, units and descriptions are the
file's, `long_name` too (CF readers label a variable by it; a file written
before slidesim wrote it gets its description). Felt accelerations
(multiples of |g|) are marked `felt_acceleration_in`: the file's units
('gravity', standard gravity, or the run's |g| as '9.81 m/s^2'; 'g' in files
written with units '1'), and the axis of /rider/acceleration_g
(the pelvis axes, not x, y, z) is `felt_axis` = longitudinal, lateral, normal.
An axis over x, y, z is `xyz` (0, 1, 2, with the labels `xyz_name`); the
second axis of a 3 x 3 matrix (rotation, frame) `xyz_2`.

    run = slidesim.open('ride.h5')
    run.groups                   # ['/evaluation', '/geometry/centerline', ...]
    run['/rider/pelvis']         # xarray.Dataset with the coordinate time
    run.ride_report()            # pandas DataFrame of /evaluation
"""
import os

from ._needs import need
from .results import ResultFileError, open_result   # names a missing h5py or numpy

try:
    import h5py
    import numpy as np
    import pandas as pd
    import xarray as xr
except ModuleNotFoundError as error:
    raise need(error) from None

FELT_AXES = ("longitudinal", "lateral", "normal")
CONTACTS = ("pelvis", "heels", "back")


def _text(value):
    return value.decode("utf-8") if isinstance(value, bytes) else value


def _attrs(obj):
    return {key: _text(value) for key, value in obj.attrs.items()
            if key not in ("DIMENSION_LIST", "REFERENCE_LIST", "CLASS", "NAME")}


def _values(d):
    return d.asstr()[()] if h5py.check_string_dtype(d.dtype) else d[()]


def is_felt_acceleration(attrs):
    """A dataset in multiples of |g| (a felt acceleration), as its description says."""
    return "|g|" in attrs.get("description", "")


def felt_units(attrs):
    """The unit of a felt acceleration: the file's ('gravity' or '9.81 m/s^2'),
    or 'g' where an older file wrote '1'."""
    units = attrs.get("units", "")
    return units if units not in ("", "1") else "g"


def _variable_attrs(d):
    attrs = _attrs(d)
    if attrs.get("description") and "long_name" not in attrs:   # a file from before long_name
        attrs["long_name"] = attrs["description"]
    if is_felt_acceleration(attrs):
        attrs["felt_acceleration_in"] = felt_units(attrs)
    return attrs


def _is_felt_axes(d, axis):
    """Axis `axis` of d runs over the pelvis axes (longitudinal, lateral, normal)."""
    description = _text(d.attrs.get("description", ""))
    return d.shape[axis] == 3 and all(word in description for word in FELT_AXES)


class Run:
    """An open slidesim result (slidesim.open): its groups as xarray Datasets."""

    def __init__(self, path):
        self.path = os.fspath(path)
        with open_result(self.path) as result:   # refuses what is not a result
            self.attrs = result.attrs
            self.layout_version = result.layout_version
            self.groups = self._groups(result.file)
            self.input_text = result.input_text if "/input/namelist" in result else ""

    @staticmethod
    def _groups(f):
        found = []

        def visit(name, obj):
            if name == "xdmf" or name.startswith("xdmf/"):
                return   # the XDMF view's copies of other groups' numbers (docs/outputs.md)
            if isinstance(obj, h5py.Group) and any(isinstance(v, h5py.Dataset) for v in obj.values()):
                found.append("/" + name)
        f.visititems(visit)
        return sorted(found)

    scenario = property(lambda self: self.attrs["scenario"])
    status = property(lambda self: self.attrs.get("status", ""))
    status_message = property(lambda self: self.attrs.get("status_message", ""))

    def __repr__(self):
        return f"<slidesim.Run {self.path}: {self.scenario}, {self.status}, groups {', '.join(self.groups)}>"

    def __iter__(self):
        return iter(self.groups)

    def __contains__(self, group):
        return "/" + group.strip("/") in self.groups

    def __getitem__(self, group):
        """The datasets directly in `group` (e.g. '/rider' or 'rider/pelvis')
        as an xarray Dataset with every axis's coordinate."""
        group = "/" + group.strip("/")
        if group not in self.groups:
            raise KeyError(f"{self.path}: no group {group} with datasets in this {self.scenario} result; "
                           f"it has {', '.join(self.groups)} (docs/outputs.md)")
        with h5py.File(self.path, "r") as f:
            return self._dataset(f, group)

    def datasets(self):
        """Every group's Dataset, by group name."""
        with h5py.File(self.path, "r") as f:
            return {group: self._dataset(f, group) for group in self.groups}

    def _dataset(self, f, group):
        g = f[group]
        data_vars, coords, dim_of_scale = {}, {}, {}

        def dim_name(scale):
            """One name per scale: its own, or with its group's if taken."""
            if scale.name not in dim_of_scale:
                parts = scale.name.strip("/").split("/")
                name = parts[-1]
                if name in dim_of_scale.values():
                    name = "_".join(parts[-2:])
                dim_of_scale[scale.name] = name
                values = _values(scale)
                coords[name] = ((name,), values, _variable_attrs(scale))
                if parts[-1] == "xyz" and len(values) == 3:
                    coords[name + "_name"] = ((name,), np.array(["x", "y", "z"]))
            return dim_of_scale[scale.name]

        for name, d in g.items():
            if not isinstance(d, h5py.Dataset):
                continue
            if h5py.h5ds.is_scale(d.id) and d.ndim == 1:
                dim_name(d)
                continue
            dims = []
            for axis, dim in enumerate(d.dims):
                if _is_felt_axes(d, axis):
                    dims.append("felt_axis")
                    coords["felt_axis"] = (("felt_axis",), np.array(FELT_AXES))
                elif len(dim):
                    dims.append(dim_name(dim[0]))
                    if dims[-1] in dims[:-1]:   # a 3 x 3 matrix over xyz twice: its second axis xyz_2
                        first = dims[-1]
                        dims[-1] = f"{first}_{dims.count(first)}"
                        coords.setdefault(dims[-1], ((dims[-1],), coords[first][1], coords[first][2]))
                else:   # no scale (not in layout 1): the axis's index
                    dims.append(f"{name}_index{axis}")
                    coords[dims[-1]] = ((dims[-1],), np.arange(d.shape[axis]))
            data_vars[name] = (tuple(dims), _values(d), _variable_attrs(d))
        attrs = _attrs(g)
        attrs["group"] = group
        attrs["file"] = self.path
        return xr.Dataset(data_vars, coords=coords, attrs=attrs)

    def ride_report(self):
        """The ride's report (/evaluation) as a pandas DataFrame, one row per
        figure (index: its name, e.g. 'top_speed', 'pelvis/wall_angle_max'):
        value, units (felt accelerations: the file's, see felt_units), where
        (the pelvis's centerline arc length, m, where the file gives it) and
        description. A ride or sweep-free scenario without /evaluation is
        refused."""
        if "/evaluation" not in self.groups:
            raise ResultFileError(f"{self.path}: a '{self.scenario}' result, which has no ride report "
                                  "(/evaluation: scenario ride)")
        rows = []
        with h5py.File(self.path, "r") as f:
            for prefix, group in [("", "/evaluation")] + [
                    (c + "/", f"/evaluation/{c}") for c in CONTACTS if f"/evaluation/{c}" in f]:
                g = f[group]
                for name, d in g.items():
                    if not isinstance(d, h5py.Dataset) or name.endswith("arc_length"):
                        continue
                    attrs = _attrs(d)
                    where = next((g[w][()] for w in (name + "_arc_length",
                                                     "wall_arc_length" if name.startswith("wall_") else "")
                                  if w and w in g), np.nan)
                    units = felt_units(attrs) if is_felt_acceleration(attrs) else attrs.get("units", "")
                    rows.append((prefix + name, _values(d), units, float(where), attrs.get("description", "")))
        frame = pd.DataFrame(rows, columns=["figure", "value", "units", "where_arc_length_m", "description"])
        return frame.set_index("figure")

    def limits(self):
        """The user's limits and their verdicts (/evaluation/limits) as a
        pandas DataFrame, one row per limit in input order (empty if none)."""
        columns = ["quantity", "given_unit", "minimum", "maximum", "verdict", "worst", "worst_arc_length",
                   "excess", "first_arc_length"]
        rows = []
        with h5py.File(self.path, "r") as f:
            if "/evaluation/limits" in f:
                g = f["/evaluation/limits"]
                for name in sorted(g, key=lambda n: int(n.split("_")[0])):
                    rows.append([_values(g[name][c]) if c in g[name] else np.nan for c in columns])
                    rows[-1].insert(0, name)
        return pd.DataFrame(rows, columns=["limit"] + columns).set_index("limit")
