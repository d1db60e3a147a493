"""The felt accelerations of a ride are in a unit that says which g
(tests/cli/felt_units.sh): every felt dataset (a description with |g|: the
/rider/acceleration_g, /evaluation/acceleration_*, the bounds, worst and
excess of an acceleration limit) and every felt number of the JSON summary
has units that pint and UDUNITS-2 both read as |g| m/s^2, |g| the run's:
'gravity' for standard gravity (9.80665 m/s^2), else the number, '9.81 m/s^2'.

    check_felt_units.py GRAVITY_M_PER_S2 EXPECTED_UNITS FILE.h5 SUMMARY.json

Prints one line per failure; exit status 1 if any.
"""
import json
import re
import subprocess
import sys

import h5py
import pint

# rtol 1e-12: the unit's number has the shortest digits that read back as
# |g| (17 at most), so pint's product differs from |g| by rounding only
RTOL = 1e-12
UNITS = pint.UnitRegistry()
failures = []


def fail(message):
    failures.append(message)
    print("FAIL " + message)


def check_units(where, units, gravity, expected):
    if units != expected:
        fail(f"{where}: units {units!r}, expected {expected!r}")
    try:
        quantity = UNITS(units)
        value = quantity.to('m/s^2').magnitude
    except Exception as error:   # pint raises several kinds (and '1' has no .to)
        fail(f"{where}: units {units!r} are not an acceleration to pint ({error})")
    else:
        if abs(value - gravity) > RTOL * gravity:
            fail(f"{where}: units {units!r} are {value} m/s^2 to pint, the run's |g| is {gravity}")
    run = subprocess.run(['udunits2', '-H', units, '-W', 'm/s^2'], capture_output=True, text=True, check=False)
    # first line "1 gravity = 9.80665 m/s^2", or "9.81 m/s^2 = 9.81 m/s^2" (the factor in the unit)
    said = run.stdout + run.stderr
    match = re.match(r'\s*(?:1 )?' + re.escape(units) + r' = ([0-9.eE+-]+) m/s\^2\s*$', said.splitlines()[0] if said else '')
    if run.returncode != 0 or not match:
        fail(f"{where}: units {units!r} not converted to m/s^2 by UDUNITS-2 ({said.strip()})")
    elif abs(float(match.group(1)) - gravity) > RTOL * gravity:
        fail(f"{where}: UDUNITS-2 reads {units!r} as {match.group(1)} m/s^2, the run's |g| is {gravity}")


def main(gravity, expected, h5_path, json_path):
    gravity = float(gravity)
    felt = []
    with h5py.File(h5_path, 'r') as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and '|g|' in obj.attrs.get('description', ''):
                felt.append(('/' + name, obj.attrs['units']))
        f.visititems(visit)
        if 'limits' in f['/evaluation']:
            for limit in f['/evaluation/limits']:
                if '_acceleration_' in limit:
                    for key in ('maximum', 'worst', 'excess'):
                        path = f'/evaluation/limits/{limit}/{key}'
                        if path in f:
                            felt.append((path, f[path].attrs['units']))
    names = {name for name, _ in felt}
    for name in ['/rider/acceleration_g'] + [f'/evaluation/acceleration_{a}_{m}' for a in ('longitudinal', 'lateral',
                                                                                         'normal') for m in ('max', 'min')]:
        if name not in names:
            fail(f"{h5_path}: {name} is not among the felt accelerations found")
    if not any('/limits/' in name for name in names):
        fail(f"{h5_path}: no acceleration limit (the test's input gives one)")
    for name, units in felt:
        check_units(f"{h5_path} {name}", units, gravity, expected)
    summary = json.load(open(json_path, encoding='utf-8'))
    keys = [k for k in summary['values'] if k.startswith('felt_') and not k.endswith('arc_length')]
    if len(keys) < 6:
        fail(f"{json_path}: felt keys {keys}")
    for key in keys:
        check_units(f"{json_path} {key}", summary['units'][key], gravity, expected)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main(*sys.argv[1:]))
