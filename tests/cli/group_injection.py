#!/usr/bin/env python3
"""Group injection (issue 27, point 1): every group in every input file is
used or refused.

For every scenario, a shipped input (and, where the slide comes from a
geometry file, that file too) gets each namelist group the scenario does not
read in that input added at its end, empty (`&group /`): an empty group
changes nothing if it is read, so only a refusal tells that it was seen.
Every such run of `slidesim --check` must exit 1 and name the file and the
line of the added group and the group itself (`FILE:LINE` and `&group`).
The groups come from the templates of every scenario (inputs/templates), so
that a group added to any scenario is injected into all the others.

usage: group_injection.py SLIDESIM ROOT
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

GEOMETRY = {'geometry', 'centerline', 'cross_section', 'slide_elements', 'blended', 'bspline'}
RIDE = {'run', 'solver', 'water_solver', 'surface', 'water', 'rider'}
GATED = RIDE | {'evaluation'}   # ride and sweep: &evaluation fail_on_limit

# (scenario, input under inputs/, the groups it reads there, geometry file it names or None,
#  the groups the geometry file is read for)
CASES = [
    ('ride', 'ride/demo_slide.nml', GATED, None, None),
    ('water', 'water/demo_slide.nml', {'run', 'solver', 'surface', 'water'},
     'demo_slide/slide.nml', {'run', 'grid', 'geometry', 'slide_elements', 'cross_section'}),
    ('water', 'WATER_CHANNEL', {'run', 'solver', 'channel', 'water'}, None, None),
    ('water', 'WATER_INLINE', {'run', 'solver', 'surface', 'water', 'geometry', 'slide_elements', 'cross_section'},
     None, None),
    ('ride', 'RIDE_NO_SURFACE', {'run', 'water', 'rider', 'solver', 'water_solver', 'surface', 'evaluation'},
     None, None),
    ('geometry', 'geometry/helix_tube.nml', {'run', 'geometry', 'centerline', 'cross_section', 'grid'}, None, None),
    ('geometry', 'geometry/blend_cylinders.nml', {'run', 'geometry', 'blended', 'grid'}, None, None),
    ('point_mass', 'point_mass/ellipsoid.nml', {'run', 'solver', 'surface', 'point_mass'}, None, None),
    ('point_mass', 'POINT_MASS_DEFAULT', {'run', 'solver', 'point_mass', 'surface'}, None, None),
    ('point_mass', 'demo_slide/point_mass.nml', {'run', 'solver', 'surface', 'point_mass'}, None, None),
    ('pendulum', 'pendulum/simple.nml', {'run', 'solver', 'pendulum'}, None, None),
    ('fourbar', 'fourbar/crank_rocker.nml', {'run', 'solver', 'fourbar'}, None, None),
    ('sled', 'sled/bowl.nml', {'run', 'solver', 'surface', 'sled', 'evaluation'}, None, None),
    ('contact', 'contact/paraboloids.nml', {'run', 'solver', 'contact_model', 'shape', 'body', 'contact'},
     'contact/paraboloids/bowl_2.geo', {'run', 'grid', 'geometry', 'bspline'}),
    ('optimize', 'design/optimize_table_4_12.nml', {'run', 'solver', 'optimize'}, None, None),
    ('sweep', 'sweep/demo_population.nml', GATED | {'sweep'}, None, None),
    ('identify_rider', 'design/identify_rider_demo.nml', RIDE | {'identify'}, None, None),
    ('identify_water', 'design/identify_water_demo.nml', {'run', 'solver', 'surface', 'water', 'identify'},
     None, None),
]

# inputs written here: a water run on &channel, a water run on a slide given in
# the input itself, a ride and a point mass without &surface
WRITTEN = {
    'WATER_CHANNEL': "&run scenario = 'water' /\n&channel length = 20.0 /\n&water flow_rate = 0.004 /\n",
    'WATER_INLINE': "&run scenario = 'water' /\n&surface kind = 'slide' /\n&water flow_rate = 0.004 /\n"
                    "&slide_elements n_elements = 2, kind = 'straight', 'runout', length = 20.0, 5.0,\n"
                    "  slope_deg = 10.0, 1.0 /\n&cross_section radius = 0.5 /\n",
    'RIDE_NO_SURFACE': "&run scenario = 'ride' /\n&water flow_rate = 0.004 /\n&rider /\n",
    'POINT_MASS_DEFAULT': "&run scenario = 'point_mass' /\n&point_mass /\n",
}


def all_groups(root):
    """Every group of every scenario's template, and the geometry groups."""
    groups = set(GEOMETRY) | {'channel', 'grid'}
    folder = os.path.join(root, 'inputs', 'templates')
    for name in os.listdir(folder):
        if not name.endswith('.nml'):
            continue   # specs/: what the templates are generated from
        with open(os.path.join(folder, name), encoding='utf-8') as f:
            groups |= {m.group(1).lower() for m in re.finditer(r'^\s*&(\w+)', f.read(), re.M)}
    return groups


def main():
    slidesim, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    universe = all_groups(root)
    work = tempfile.mkdtemp(prefix='slidesim_groups_')
    failures, runs = [], 0
    try:
        tree = os.path.join(work, 'inputs')
        shutil.copytree(os.path.join(root, 'inputs'), tree)
        for name, text in WRITTEN.items():
            with open(os.path.join(tree, name + '.nml'), 'w', encoding='utf-8') as f:
                f.write(text)
        scenarios_seen = set()
        for scenario, main_input, reads, geometry_file, geometry_reads in CASES:
            main_path = os.path.join(tree, main_input if main_input.endswith('.nml') else main_input + '.nml')
            scenarios_seen.add(scenario)
            targets = [(main_path, universe - reads)]
            if geometry_file:
                targets.append((os.path.join(tree, geometry_file), universe - geometry_reads))
            # the unchanged input passes
            p = subprocess.run([slidesim, '-q', '--check', os.path.basename(main_path)],
                               cwd=os.path.dirname(main_path), capture_output=True, timeout=120)
            if p.returncode != 0:
                failures.append(f'{main_input}: exit {p.returncode} without an added group: '
                                f'{p.stderr.decode()[:300]}')
                continue
            for target, unused in targets:
                with open(target, encoding='utf-8') as f:
                    original = f.read()
                for group in sorted(unused):
                    text = original if original.endswith('\n') else original + '\n'
                    line = text.count('\n') + 1
                    with open(target, 'w', encoding='utf-8') as f:
                        f.write(text + f'&{group} /\n')
                    runs += 1
                    p = subprocess.run([slidesim, '-q', '--check', os.path.basename(main_path)],
                                       cwd=os.path.dirname(main_path), capture_output=True, timeout=120)
                    err = p.stderr.decode('utf-8', 'replace')
                    label = f'{scenario}: &{group} added to {os.path.relpath(target, tree)} (line {line})'
                    place = f'{os.path.basename(target)}:{line}'
                    if p.returncode != 1:
                        failures.append(f'{label}: exit {p.returncode}, not 1 (the group is ignored): {err[:300]}')
                    elif place not in err or f'&{group}' not in err:
                        failures.append(f'{label}: the message does not name {place} and &{group}: {err[:400]}')
                with open(target, 'w', encoding='utf-8') as f:
                    f.write(original)
        # every scenario (one template each) has a case
        for name in sorted(os.listdir(os.path.join(root, 'inputs', 'templates'))):
            if name.endswith('.nml') and name[:-4] not in scenarios_seen:
                failures.append(f'scenario {name[:-4]} has no case in the group injection')
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f'group injection: {runs} inputs with a group their scenario does not read, {len(failures)} failures')
    for failure in failures:
        print('FAIL ' + failure)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
