"""Checks a --summary-json file against the HDF5 result of the same run.

    check_summary_json.py [--reference INPUT_REFERENCE.md] SUMMARY.json RESULT.h5 PRINTED_SUMMARY.txt [...]

The JSON must load, name the scenario, status and result file of the HDF5
file, give a pint-parsable unit for every number, hold the keys this scenario's
summary promises (docs/outputs.md, "Summary JSON"), and each number must equal
what the HDF5 file holds. Tolerance: values copied from the series are written
as shortest round-trip decimals and compared exactly up to 1e-12 relative,
which also covers quantities recomputed here with numpy (norms, differences,
ratios: a few roundings). With --reference (the output of `slidesim
--input-reference`), a number that echoes an input variable (a key named as
a variable of a group the run's input gives, e.g. the water's flow_rate, the
optimisation's lever_limit) must carry the unit declared for it. Prints
failures; exit status 1 if any.
"""
import json
import re
import sys

import h5py
import numpy as np
import pint

failures = []
RTOL = 1e-12
MULTIBODY = ('pendulum', 'fourbar', 'sled', 'contact')


def fail(message):
    failures.append(message)


def close(name, got, expected):
    got = np.asarray(got, dtype=float)
    expected = np.asarray(expected, dtype=float)
    if got.shape != expected.shape or not np.allclose(got, expected, rtol=RTOL, atol=1e-300):
        fail(f"{name}: JSON {got.tolist()} but the HDF5 file gives {expected.tolist()}")


def check_element_design(g, values, need, close):
    """An element design of optimize: each variable (start, optimum[, nearest, catalogue]; SI: angles in
    rad) and, with a catalogue, the costs and the parts counted."""
    k = 1
    while f'variables/variable_{k}' in g:
        v = g[f'variables/variable_{k}']
        names = ('start', 'optimum', 'nearest', 'catalogue') if 'catalogue' in v else ('start', 'optimum')
        scale = np.pi / 180 if v['start'].attrs['units'] == 'degree' else 1.0
        if need(f'variable_{k}'):
            close(f'variable_{k}', values[f'variable_{k}'], [float(v[n][()]) * scale for n in names])
        k += 1
    if 'parts' in g and need('acceleration_cost', 'catalogue_acceleration_cost', 'elements', 'parts'):
        close('acceleration_cost', values['acceleration_cost'], g['after/acceleration_cost'][()])
        close('catalogue_acceleration_cost', values['catalogue_acceleration_cost'], g['chosen/acceleration_cost'][()])
        close('elements', values['elements'], g['parts/count'][:].sum())
        close('parts', values['parts'], g['parts/count'].shape[0])


def check_contact(g, values, need):
    """The contact summary in bodies' and contacts' terms (docs/outputs.md):
    energy in J, per contact slip, normal and friction forces, per body the
    tilt and spin of its symmetry axis, which must be one of the body axes
    the file holds as rows of `rotation` (rotation[i, k, :])."""
    energy = g['kinetic_energy'][:] + g['potential_energy'][:]
    if need('energy_change_joules'):
        close('energy_change_joules', values['energy_change_joules'], energy[-1] - energy[0])
    for contact in g.get('contacts', {}):
        c = g['contacts'][contact]
        if 'velocity' not in c:
            continue   # open at every record (a flight that never closed): no slip or forces, none in the summary
        # a flight's contact counts while closed (open == 0): open, its velocity
        # is the flight's relative speed; the final slip only if closed at the end
        closed = c['open'][:] == 0 if 'open' in c else np.ones(len(c['velocity']), bool)
        if not closed.any():
            if any(key.startswith(contact + '_') for key in values):
                fail(f'{contact}: open at every record, yet in the summary')
            continue
        slip = np.linalg.norm(c['velocity'][:], axis=1)
        keys = [contact + k for k in ('_slip_speed_max', '_normal_force_min',
                                      '_normal_force_max', '_friction_force_max')]
        if need(*keys):
            close(keys[0], values[keys[0]], slip[closed].max())
            close(keys[1], values[keys[1]], c['normal_force'][:][closed].min())
            close(keys[2], values[keys[2]], c['normal_force'][:][closed].max())
            close(keys[3], values[keys[3]], np.linalg.norm(c['friction_force'][:], axis=1)[closed].max())
        final = contact + '_slip_speed_final'
        if closed[-1] and need(final):
            close(final, values[final], slip[-1])
        elif not closed[-1] and final in values:
            fail(f'{final}: the contact is open at the end, yet a final slip speed is reported')
    for body in g['bodies']:
        b = g['bodies'][body]
        need(body + '_height_final', body + '_height_min', body + '_height_max', body + '_speed_max')
        if body + '_tilt_final' not in values:
            need(body + '_angular_speed_final', body + '_angular_speed_max')
            continue
        rot, omega = b['rotation'][-1], b['angular_velocity'][-1]
        # rows: the body axes (z up in these inputs); atan2, as the summary: arccos of the z part
        # loses the angle near upright (egg_long_axis_z ends 4.6e-4 rad off: 5e-10 relative)
        tilts = np.arctan2(np.hypot(rot[:, 0], rot[:, 1]), rot[:, 2])
        k = int(np.argmin(np.abs(tilts - values[body + '_tilt_final'])))
        close(body + '_tilt_final', values[body + '_tilt_final'], tilts[k])
        if need(body + '_spin_final'):
            close(body + '_spin_final', values[body + '_spin_final'], omega @ rot[k])


def declared_units(reference_path):
    """{(group, scenario or None): {variable: unit}} from the reference tables;
    a heading '&identify (scenario identify_rider)' holds that scenario's group."""
    tables, current = {}, None
    for line in open(reference_path, encoding='utf-8'):
        heading = re.match(r'### &(\w+)(?: \(scenario (\w+)\))?', line)
        if heading:
            current = tables.setdefault((heading.group(1), heading.group(2)), {})
            continue
        row = re.match(r'\| `(\w+)` \|.*\| ([^|]*) \| ([^|]*) \| ([^|]*) \|$', line.rstrip('\n'))
        if row and current is not None:
            current[row.group(1)] = row.group(2).strip()
    return tables


def check_echoed_units(values, units, scenario, namelist, reference):
    """Every summary number named as an input variable of a group the input
    gives carries that variable's declared unit."""
    groups = set(re.findall(r'^\s*&(\w+)', namelist, re.M))
    for key, value in values.items():
        if isinstance(value, str) or (isinstance(value, list) and value and isinstance(value[0], dict)):
            continue   # a text or a table (the stations), not an input's value
        declared = {table[key] for (group, only), table in reference.items()
                    if group in groups and only in (None, scenario) and key in table}
        if declared and units.get(key) not in declared:
            fail(f"{key}: unit {units.get(key)!r}, but the input variable {key} is declared in "
                 f"{' or '.join(sorted(declared))}")


def check(json_path, h5_path, printed_path, reference=None):
    failures.clear()
    summary = json.load(open(json_path, encoding='utf-8'))
    values, units = summary['values'], summary['units']
    f = h5py.File(h5_path, 'r')
    scenario = f.attrs['scenario']
    if reference is not None:
        namelist = f['/input/namelist'][()]
        check_echoed_units(values, units, scenario,
                           namelist.decode() if isinstance(namelist, bytes) else str(namelist), reference)
    if summary['scenario'] != scenario:
        fail(f"scenario {summary['scenario']!r}, the file says {scenario!r}")
    if summary['status'] != f.attrs['status'] or summary['status_message'] != f.attrs['status_message']:
        fail(f"status {summary['status']!r}/{summary['status_message']!r} differs from the file's")
    if summary['result_file'] != h5_path:
        fail(f"result_file {summary['result_file']!r}, expected {h5_path!r}")
    if summary['result_file'] not in open(printed_path, encoding='utf-8').read():
        fail("the printed summary does not name the result file")
    registry = pint.UnitRegistry()
    for key, value in values.items():
        if isinstance(value, str):
            continue
        if isinstance(value, list) and value and isinstance(value[0], dict):
            keys = [f"{key}.{column}" for column in value[0]]
        else:
            keys = [key]
        for k in keys:
            if k not in units:
                fail(f"{k}: no unit in the units map")
            else:
                try:
                    registry(units[k])   # an expression: '9.81 m/s^2' (felt accelerations) has a factor
                except Exception as error:   # pint raises several kinds
                    fail(f"{k}: unit {units[k]!r} not parsed by pint ({error})")

    def need(*keys):
        missing = [k for k in keys if k not in values]
        if missing:
            fail(f"keys missing: {missing}")
        return not missing

    stats = ('steps', 'rhs_evaluations', 'cpu_time')
    # each stage keeps its statistics in its own group (/water/statistics);
    # a multibody run's are /statistics (a sled's water beside it has its own)
    statistics = '/water/statistics' if '/water/statistics' in f and scenario not in MULTIBODY else '/statistics'
    if scenario in ('water', 'point_mass') + MULTIBODY and need(*stats):   # one integrator run each
        close('steps', values['steps'], f[statistics + '/steps'][()])
        close('rhs_evaluations', values['rhs_evaluations'], f[statistics + '/rhs_evaluations'][()])
        close('cpu_time', values['cpu_time'], f[statistics + '/cpu_time'][()])

    if scenario == 'water':
        g = f['/water']
        if need('flow_rate', 'flow_time', 'slide_length_covered', 'outcome', 'speed_min', 'speed_max',
                'final_speed', 'height_min', 'height_max', 'width_min', 'width_max', 'flow_angle_min',
                'flow_angle_max', 'v_min', 'v_max'):
            close('flow_rate', values['flow_rate'], g.attrs['flow_rate_m3_per_s'])
            close('flow_time', values['flow_time'], g['time'][-1])
            close('slide_length_covered', values['slide_length_covered'], g['arc_length'][-1] - g['arc_length'][0])
            if values['outcome'] != g.attrs['outcome']:
                fail(f"outcome {values['outcome']!r}, the file says {g.attrs['outcome']!r}")
            for key, name in (('speed', 'speed'), ('height', 'height'), ('width', 'width'),
                              ('flow_angle', 'beta'), ('v', 'v')):
                close(key + '_min', values[key + '_min'], g[name][:].min())
                close(key + '_max', values[key + '_max'], g[name][:].max())
            close('final_speed', values['final_speed'], g['speed'][-1])
        if 'stations' in g and need('stations'):
            rows = values['stations']
            for column in ('time', 'speed', 'height', 'width', 'v_middle', 'v_left', 'v_right', 'u'):
                close('stations.' + column, [r[column] for r in rows], g['stations/' + column][:])
            close('stations.arc_length', [r['arc_length'] for r in rows], g['stations/arc_length'][:])
            close('stations.reached', [r['reached'] for r in rows], g['stations/reached'][:])
    elif scenario == 'point_mass':
        g = f['/point_mass']
        if need('simulated_time', 'final_position', 'final_speed', 'max_speed', 'max_acceleration',
                'normal_force_min', 'normal_force_max', 'drop', 'friction_work', 'energy_balance_error'):
            close('simulated_time', values['simulated_time'], g['time'][-1])
            close('final_position', values['final_position'], g['position'][-1])
            close('final_speed', values['final_speed'], g['speed'][-1])
            close('max_speed', values['max_speed'], g['speed'][:].max())
            close('max_acceleration', values['max_acceleration'], np.linalg.norm(g['acceleration'][:], axis=1).max())
            close('normal_force_min', values['normal_force_min'], g['normal_force'][:].min())
            close('normal_force_max', values['normal_force_max'], g['normal_force'][:].max())
            close('drop', values['drop'], g['position'][0, 2] - g['position'][-1, 2])
            close('friction_work', values['friction_work'], g['friction_work'][-1])
    elif scenario == 'ride':
        # the ride's report (docs/rider.md): a few of its numbers against the series
        g = f['/rider']
        if need('ride_time', 'distance', 'top_speed', 'ride_steps'):
            close('ride_time', values['ride_time'], g['time'][-1] - g['time'][0])
            close('distance', values['distance'], g['arc_length'][-1] - g['arc_length'][0])
            # located between the records (docs/accuracy.md): at least the
            # records' largest speed, and above it by no more than a smooth
            # peak gains between records 0.01 s apart (|dv/dt| changes by a few
            # m/s^3: jerk dt^2/8 ~ 1e-4 m/s; 8e-6 relative on the default ride)
            top, recorded = values['top_speed'], g['speed'][:].max()
            if not recorded <= top <= recorded * (1 + 1e-4):
                fail(f"top_speed: JSON {top} is not within 1e-4 above the HDF5 series' largest speed {recorded}")
            close('ride_steps', values['ride_steps'], g['statistics/steps'][()])
        if 'airborne' in g:
            # with may_fly (docs/rider.md "What the felt figures cover"): the time
            # the felt figures leave out, that of the records with the pelvis in
            # the air while another contact is on, or alone on the slide
            airborne, time = g['airborne'][:], g['time'][:]
            left_out = np.isin(airborne, [1, 3, 5, 6])[:-1]
            if need('felt_not_judged_time'):
                close('felt_not_judged_time', values['felt_not_judged_time'],
                      f['/evaluation/flight/felt_not_judged_time'][()])
                if not abs(values['felt_not_judged_time'] - np.diff(time)[left_out].sum()) <= 1e-9:
                    fail(f"felt_not_judged_time: {values['felt_not_judged_time']} s, but the records with the "
                         f"pelvis in the air or alone on the slide span {np.diff(time)[left_out].sum()} s")
    elif scenario == 'geometry':
        if need('grid_n_u', 'grid_n_v'):
            close('grid_n_u', values['grid_n_u'], f['/geometry/surface/u'].shape[0])
            close('grid_n_v', values['grid_n_v'], f['/geometry/surface/v'].shape[0])
        if '/geometry/centerline' in f and need('centerline_length', 'drop', 'curvature_max'):
            c = f['/geometry/centerline']
            close('centerline_length', values['centerline_length'], c['length'][()])
            close('drop', values['drop'], c['points'][0, 2] - c['points'][-1, 2])
            close('curvature_max', values['curvature_max'], c['chi'][:].max())
    elif scenario == 'optimize':
        g = f['/optimize']
        points = 'x_start' in g   # else an element design: /optimize/variables
        if need('cost_start', 'lever_limit', 'evaluations', 'cpu_time', 'rides') and (not points or need('design')):
            close('cost_start', values['cost_start'], g['cost_start'][()])
            close('lever_limit', values['lever_limit'], g['lever_limit'][()])
            close('evaluations', values['evaluations'], g['evaluations'][()])
            close('cpu_time', values['cpu_time'], g['cpu_time'][()])
            rides = values['rides']
            if points:
                design = values['design']
                close('design.point', [r['point'] for r in design], g['design_point'][:])
                close('design.coordinate', [r['coordinate'] for r in design], g['design_coordinate'][:])
                close('design.start', [r['start'] for r in design], g['x_start'][:])
            close('rides.start_angle', [r['start_angle'] for r in rides], np.degrees(g['before/start_angle'][:]))
            close('rides.max_a_start', [r['max_a_start'] for r in rides], g['before/max_acceleration'][:])
            close('rides.lever_arm_start', [r['lever_arm_start'] for r in rides], g['before/max_lever_arm'][:])
            if 'centerline' in g and need('cost'):
                close('cost', values['cost'], g['cost'][()])
                if points:
                    close('design.optimum', [r['optimum'] for r in design], g['x'][:])
                    close('design.move', [r['move'] for r in design], g['x'][:] - g['x_start'][:])
                close('rides.max_a_optimum', [r['max_a_optimum'] for r in rides], g['after/max_acceleration'][:])
                close('rides.lever_arm_optimum', [r['lever_arm_optimum'] for r in rides],
                      g['after/max_lever_arm'][:])
            if not points and 'centerline' in g:
                check_element_design(g, values, need, close)
    elif scenario in MULTIBODY:
        g = f['/' + scenario]
        if need('simulated_time', 'energy_change'):
            close('simulated_time', values['simulated_time'], g['time'][-1])
            kinetic, potential = g['kinetic_energy'][:], g['potential_energy'][:]
            scale = max(kinetic.max(), np.abs(potential - potential[0]).max())
            close('energy_change', values['energy_change'],
                  (kinetic[-1] + potential[-1] - kinetic[0] - potential[0]) / scale)
        if scenario == 'contact':
            check_contact(g, values, need)
        for q in (g['coordinates'] if scenario != 'contact' else ()):
            c = g['coordinates'][q]
            if need(q + '_final', q + '_min', q + '_max', q + '_rate_final'):
                close(q + '_final', values[q + '_final'], c['value'][-1])
                close(q + '_min', values[q + '_min'], c['value'][:].min())
                close(q + '_max', values[q + '_max'], c['value'][:].max())
                close(q + '_rate_final', values[q + '_rate_final'], c['rate'][-1])
            if c['value'].attrs['units'] == 'rad' and need(q + '_rate_max'):
                close(q + '_rate_max', values[q + '_rate_max'], np.abs(c['rate'][:]).max())
        if 'closure_residual' in g and need('closure_residual_max'):
            close('closure_residual_max', values['closure_residual_max'], g['closure_residual'][:].max())
        for contact in (g.get('contacts', {}) if scenario != 'contact' else ()):
            c = g['contacts'][contact]
            if need(contact + '_speed_max', contact + '_normal_force_min', contact + '_normal_force_max'):
                close(contact + '_speed_max', values[contact + '_speed_max'],
                      np.linalg.norm(c['velocity'][:], axis=1).max())
                close(contact + '_normal_force_min', values[contact + '_normal_force_min'], c['normal_force'][:].min())
                close(contact + '_normal_force_max', values[contact + '_normal_force_max'], c['normal_force'][:].max())
    else:   # a scenario this check does not know yet: the generic checks above only
        print(f"note: {json_path}: scenario {scenario!r} has no value checks here")
    for line in failures:
        print(f"FAIL {json_path}: {line}")
    return len(failures)


def main(arguments):
    reference = None
    if arguments[:1] == ['--reference'] and len(arguments) > 1:
        reference = declared_units(arguments[1])
        arguments = arguments[2:]
    if not arguments or len(arguments) % 3:
        sys.exit(__doc__)
    bad = sum(check(*arguments[k:k + 3], reference) for k in range(0, len(arguments), 3))
    print(f"{len(arguments) // 3} summaries checked, {bad} failures")
    sys.exit(1 if bad else 0)


if __name__ == '__main__':
    main(sys.argv[1:])
