"""Read slidesim result files: every dataset with its units and coordinates.

The plain reader (h5py and numpy only) under slidesim.open and the plots:

    from slidesim.results import open_result
    with open_result('result.h5') as r:
        print(r.scenario, r.status)            # 'water', 'complete'
        speed = r['/water/speed']              # a Quantity
        print(speed.units, speed.values[-1])   # 'm/s', numpy array
        t = speed.coords[0]                    # ('time', values) of axis 0
        print(r.input_text[:80])

`Quantity.to_pint()` gives a pint Quantity when pint is installed. The layout
(groups, datasets, units) is described in docs/outputs.md; `layout_version`
says which version of it a file follows.
"""

from dataclasses import dataclass, field
import os

from ._needs import need

try:
    import h5py
    import numpy as np
except ModuleNotFoundError as error:
    raise need(error) from None

SUPPORTED_LAYOUT = 1


class ResultFileError(Exception):
    """The file is not a slidesim result (or not the kind asked for)."""


@dataclass
class Quantity:
    """A dataset's values with its units, description and coordinates."""
    name: str
    values: np.ndarray
    units: str
    description: str
    coords: dict = field(default_factory=dict)   # numpy axis -> (name, values)

    def to_pint(self, registry=None):
        """The values as a pint Quantity (pint must be installed). A unit with
        a factor ('9.81 m/s^2': felt accelerations under a gravity other than
        standard) scales the values."""
        import pint
        registry = registry or pint.UnitRegistry()
        unit = registry.parse_expression(self.units or '1')
        if isinstance(unit, registry.Quantity):
            return registry.Quantity(self.values * unit.magnitude, unit.units)
        return registry.Quantity(self.values * unit, 'dimensionless')


def _text(value):
    return value.decode('utf-8') if isinstance(value, bytes) else value


class Result:
    """An open slidesim result file (use open_result)."""

    def __init__(self, path):
        self.path = path
        if not os.path.exists(path):
            raise ResultFileError(f"{path}: no such file")
        try:
            self.file = h5py.File(path, 'r')
        except OSError as error:
            raise ResultFileError(f"{path}: not an HDF5 file ({error})") from None
        attrs = self.file.attrs
        if 'scenario' not in attrs or 'layout_version' not in attrs:
            self.file.close()
            raise ResultFileError(f"{path}: an HDF5 file, but not a slidesim result "
                                  "(no 'scenario' and 'layout_version' attributes at its root)")
        self.layout_version = int(attrs['layout_version'])
        if self.layout_version > SUPPORTED_LAYOUT:
            self.file.close()
            raise ResultFileError(f"{path}: layout version {self.layout_version} is newer than this "
                                  f"reader ({SUPPORTED_LAYOUT}); update the slidesim Python package (python/)")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        self.file.close()

    @property
    def attrs(self):
        """The root attributes (provenance, status) as Python values."""
        return {key: _text(value) for key, value in self.file.attrs.items()}

    @property
    def scenario(self):
        return _text(self.file.attrs['scenario'])

    @property
    def status(self):
        return _text(self.file.attrs['status'])

    @property
    def status_message(self):
        return _text(self.file.attrs.get('status_message', ''))

    @property
    def input_text(self):
        return self.file['/input/namelist'].asstr()[()]

    def __contains__(self, name):
        return name in self.file

    def group_attrs(self, group):
        return {key: _text(value) for key, value in self.file[group].attrs.items()}

    def datasets(self, under='/'):
        """Names of every dataset under a group."""
        names = []
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                names.append('/' + name)
        self.file[under].visititems(visit)
        return sorted(names)

    def __getitem__(self, name):
        if name not in self.file:
            raise KeyError(f"{self.path}: no dataset {name} in this {self.scenario} result "
                           f"(see docs/outputs.md)")
        d = self.file[name]
        if h5py.check_string_dtype(d.dtype):
            values = d.asstr()[()]
        else:
            values = d[()]
        coords = {}
        for axis, dim in enumerate(d.dims):
            for scale_name, scale in dim.items():
                coords[axis] = (scale_name or scale.name.rsplit('/', 1)[-1], scale[()])
                break
        return Quantity(name, np.asarray(values) if not isinstance(values, str) else values,
                        _text(d.attrs.get('units', '')), _text(d.attrs.get('description', '')), coords)


def open_result(path, scenario=None):
    """Opens a result file; with `scenario` (a name or a tuple of names),
    refuses a file of another scenario with a message saying which it is."""
    result = Result(path)
    wanted = (scenario,) if isinstance(scenario, str) else scenario
    if wanted and result.scenario not in wanted:
        found = result.scenario
        result.close()
        raise ResultFileError(f"{path}: a '{found}' result, but this needs a result of "
                              f"{' or '.join(repr(w) for w in wanted)}")
    return result
