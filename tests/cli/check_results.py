"""Checks slidesim result files against the conventions and the layout tables
of docs/outputs.md (run by result_conventions.sh).

    check_results.py DOCS_OUTPUTS_MD FILE.h5 [FILE.h5 ...]

For every file: strings are variable-length UTF-8 (h5py gives str); no
attribute holds a number as text; every dataset has `units` (parsed by pint
and by UDUNITS-2), `description` and `long_name`, the same text (CF); /statistics and documented scalars have
shape (); every axis of every dataset of a scenario group has a dimension
scale, and xarray (engine h5netcdf) opens every group with named dimensions
(not /xdmf, the XDMF view's copies in its layout);
the provenance attributes are present, `input_sha256` is the
SHA-256 of /input/namelist. Against the docs: every dataset in the file is
documented, with the documented shape (rank and fixed sizes) and units (where
the docs give a fixed unit), and every documented dataset not marked
"(when ...)" exists in a complete file; the status and message as the root attribute table
says (complete: `ok` and where it stopped; incomplete: why), and where the
run's exit status is known (NAME.rc beside NAME.h5, as the fixture
every_input.sh leaves it) 0 for complete, 2 for incomplete. Prints one line
per failure; exit status 1 if any.
"""
import functools
import hashlib
import os
import re
import subprocess
import sys

import h5py
import numpy as np
import pint
import xarray

UNITS = pint.UnitRegistry()
MULTIBODY = ('pendulum', 'fourbar', 'sled', 'contact')
# attributes the HDF5 dimension-scale API writes itself (fixed-length ASCII by its specification)
DS_ATTRIBUTES = ('CLASS', 'NAME', 'REFERENCE_LIST', 'DIMENSION_LIST')
NUMBER = r'[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?'
PROVENANCE = ('scenario', 'title', 'status', 'status_message', 'layout_version', 'slidesim_version',
              'git_commit', 'compiler', 'compiler_options', 'created_utc', 'host', 'input_sha256')
failures = []


@functools.lru_cache(maxsize=None)
def udunits_error(units):
    """What UDUNITS-2 (Debian's udunits-bin) says about a unit text, or ''."""
    run = subprocess.run(['udunits2', '-H', units, '-W', ''], capture_output=True, text=True, check=False)
    text = run.stdout + run.stderr
    return text.strip() if run.returncode != 0 or "Don't recognize" in text else ''


def fail(path, message):
    failures.append(f"{path}: {message}")


def parse_docs(path):
    """The dataset rows of docs/outputs.md: (regex, shape, units, required)."""
    rows = []
    for line in open(path, encoding='utf-8'):
        row = line.strip()[1:-1] if line.startswith('| `/') else None
        cells = [c.strip() for c in re.split(r'(?<!\\)\|', row)] if row else None
        if not cells or len(cells) != 4:
            continue
        names = re.findall(r'`(/[^`]+)`', cells[0])
        shape = cells[1]
        units = [u.strip() for u in cells[2].split(',')]
        required = '(when' not in cells[3]
        for k, name in enumerate(names):
            pattern = '^' + re.sub(r'<[a-z]+>', '[^/]+', re.escape(name).replace('\\<', '<').replace('\\>', '>')) + '$'
            unit = units[k] if len(units) == len(names) else units[0]
            rows.append((name, re.compile(pattern), shape, unit, required, cells[3]))
    return rows


def applies(row_name, scenario, groups=()):
    """Whether a docs row can occur in a file of this scenario (`groups`:
    the file's top-level groups)."""
    head = row_name.split('/')[1]
    if head == '<s>':
        return scenario in MULTIBODY
    if head in ('input', 'statistics', 'geometry', 'xdmf'):
        return True
    if scenario == 'ride':   # the ride's stages
        return head in ('water', 'rider', 'evaluation')
    if scenario == 'sled' and head == 'water':   # a vehicle in the water (docs/vehicles.md)
        return 'water' in groups
    return head == scenario


def shape_matches(doc_shape, shape):
    dims = [d.strip() for d in doc_shape.strip('()').split(',') if d.strip()]
    if len(dims) != len(shape):
        return False
    return all(not d.isdigit() or int(d) == s for d, s in zip(dims, shape))


def check_string(path, where, value_dtype, value):
    info = h5py.check_string_dtype(value_dtype)
    if info is None:
        return
    if info.length is not None or info.encoding != 'utf-8':
        fail(path, f"{where}: string is not variable-length UTF-8 ({info})")


def check_file(path, rows):
    f = h5py.File(path, 'r')
    scenario = f.attrs.get('scenario')
    if not isinstance(scenario, str):
        fail(path, f"root attribute scenario is {scenario!r}, not a str")
        return
    # provenance and root attributes
    for key in PROVENANCE:
        if key not in f.attrs:
            fail(path, f"root attribute {key} missing")
    status, message = f.attrs.get('status'), str(f.attrs.get('status_message'))
    if status not in ('complete', 'incomplete'):
        fail(path, f"status is {status!r}")
    if status == 'complete' and not re.match(r'ok\b', message):
        fail(path, f"complete, but status_message {message!r} does not start with 'ok'")
    if status == 'incomplete' and (not message.strip() or message.startswith('ok')):
        fail(path, f"incomplete, but status_message {message!r} says no reason")
    rc_path = path[:-3] + '.rc' if path.endswith('.h5') else None
    if rc_path and os.path.exists(rc_path):
        rc = open(rc_path).read().strip()
        if {'complete': '0', 'incomplete': '2'}.get(status) != rc:
            fail(path, f"status {status!r} but the run's exit status was {rc}")
    if not isinstance(f.attrs.get('layout_version'), (np.integer, int)):
        fail(path, f"layout_version is not an integer: {f.attrs.get('layout_version')!r}")
    if not re.fullmatch(r'\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ', str(f.attrs.get('created_utc'))):
        fail(path, f"created_utc is not ISO 8601 UTC: {f.attrs.get('created_utc')!r}")
    if not re.fullmatch(r'([0-9a-f]{40}(-dirty)?|unknown)', str(f.attrs.get('git_commit'))):
        fail(path, f"git_commit is {f.attrs.get('git_commit')!r}")
    text = f['/input/namelist'][()]
    if hashlib.sha256(text).hexdigest() != f.attrs.get('input_sha256'):
        fail(path, "input_sha256 is not the SHA-256 of /input/namelist")

    # every attribute anywhere: strings vlen UTF-8, no numbers as text
    def attributes(name, obj):
        for key, value in obj.attrs.items():
            if key in DS_ATTRIBUTES:
                continue
            where = f"/{name} attribute {key}" if name else f"/ attribute {key}"
            check_string(path, where, obj.attrs.get_id(key).dtype, value)
            if isinstance(value, bytes):
                fail(path, f"{where}: read as bytes, not str")
            if isinstance(value, str) and key not in ('units', 'description', 'long_name', 'title', 'status_message') \
                    and re.fullmatch(rf'\s*{NUMBER}(\s+{NUMBER})*\s*', value):
                fail(path, f"{where}: a number stored as text ({value!r})")
    attributes('', f)
    f.visititems(attributes)

    datasets = {}
    f.visititems(lambda name, obj: datasets.__setitem__('/' + name, obj) if isinstance(obj, h5py.Dataset) else None)
    documented = [r for r in rows if applies(r[0], scenario, tuple(f.keys()))]
    for name, d in sorted(datasets.items()):
        check_string(path, name, d.dtype, None)
        if 'units' not in d.attrs or 'description' not in d.attrs:
            fail(path, f"{name}: no units or description attribute")
            continue
        if d.attrs.get('long_name') != d.attrs['description']:
            fail(path, f"{name}: long_name {d.attrs.get('long_name')!r} is not the description")
        units = d.attrs['units']
        is_text = h5py.check_string_dtype(d.dtype) is not None
        if is_text:
            if units != '':
                fail(path, f"{name}: a text dataset with units {units!r}")
        else:
            try:
                UNITS(units)   # an expression: '9.81 m/s^2' (felt accelerations) has a factor
            except Exception as error:   # pint raises several kinds
                fail(path, f"{name}: units {units!r} not parsed by pint ({error})")
            if udunits_error(units):
                fail(path, f"{name}: units {units!r} not parsed by UDUNITS-2 ({udunits_error(units)})")
        group = name.split('/')[1]
        if name.startswith('/statistics/') and d.shape != ():
            fail(path, f"{name}: shape {d.shape}, expected a scalar ()")
        # a dimension scale on every axis of every scenario dataset (not the
        # XDMF view's copies in /xdmf: the same numbers, scaled, are in their groups)
        if group not in ('input', 'statistics', 'xdmf') and d.ndim >= 1 and not h5py.h5ds.is_scale(d.id):
            for axis in range(d.ndim):
                if len(d.dims[axis]) == 0:
                    fail(path, f"{name}: no dimension scale on axis {axis}")
        # against the docs
        match = [r for r in documented if r[1].match(name)]
        if not match:
            fail(path, f"{name}: not in docs/outputs.md")
            continue
        row_name, _, doc_shape, doc_units, _, _ = match[0]
        if not shape_matches(doc_shape, d.shape):
            fail(path, f"{name}: shape {d.shape}, docs/outputs.md says {doc_shape}")
        fixed = not (doc_units.startswith('(') or doc_units == '—')
        if doc_units == '(g)' and not re.fullmatch(rf'gravity|{NUMBER} m/s\^2', units):
            fail(path, f"{name}: units {units!r}, docs/outputs.md says (g): 'gravity' or '<|g|> m/s^2'")
        if fixed and doc_units != units:
            fail(path, f"{name}: units {units!r}, docs/outputs.md says {doc_units!r}")
        if doc_units == '—' and not is_text:
            fail(path, f"{name}: docs/outputs.md says text, the file has {d.dtype}")
    # an incomplete file holds what was computed until the run stopped
    for row in documented if status == 'complete' else []:
        if row[4] and not any(row[1].match(n) for n in datasets):
            fail(path, f"documented {row[0]} missing")
    groups = sorted({name.rsplit('/', 1)[0] for name in datasets
                     if name.split('/')[1] not in ('input', 'statistics', 'xdmf')})
    f.close()
    # xarray (netCDF reader h5netcdf) opens every group with named dimensions
    for group in groups:
        try:
            ds = xarray.open_dataset(path, group=group, engine='h5netcdf')
        except Exception as error:   # h5netcdf and xarray raise several kinds
            fail(path, f"xarray cannot open {group}: {error}")
            continue
        for var in ds.data_vars.values():
            if any(dim.startswith('phony_dim') for dim in var.dims):
                fail(path, f"{group}/{var.name}: xarray sees unnamed dimensions {var.dims}")
        ds.close()


def main():
    rows = parse_docs(sys.argv[1])
    if len(rows) < 50:
        sys.exit(f"only {len(rows)} dataset rows parsed from {sys.argv[1]}: table format changed?")
    for path in sys.argv[2:]:
        check_file(path, rows)
    for line in failures:
        print('FAIL ' + line)
    print(f"{len(sys.argv) - 2} files checked against {len(rows)} documented datasets, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == '__main__':
    main()
