#!/usr/bin/env python3
"""The layer rule of docs/DESIGN.md ("Layers"): a module in src/<layer>/ uses
only modules of its own layer and of the layers above it, in the order
src/CMakeLists.txt declares them (its slidesim_layer(...) lines). Every `use`
of every src/**/*.f90 is checked; a module no src file defines (intrinsic,
MPI, HDF5, SUNDIALS) is passed over.

The build does not catch a use against the order by itself: the layers share
one module folder, so a warm build finds a lower layer's module file and
compiles.

It checks itself first on a made-up case (a geometry module using a rider
module, and a rider module using a geometry one), so that it cannot pass by
reading nothing. Exit 0: every use in order; 1: each one against it printed
as `FAIL file:line: ...`.

    check_layers.py     (from the repository root)
"""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFINES = re.compile(r'^\s*(?:module|submodule\s*\([^)]*\))\s+(\w+)\s*$', re.I)
USES = re.compile(r'^\s*use\b(?!\s*,\s*intrinsic)\s*(?:,\s*non_intrinsic\s*)?(?:::)?\s*(\w+)', re.I)


def layer_order():
    """The layers in the order of src/CMakeLists.txt's slidesim_layer(...) lines."""
    text = open(os.path.join(ROOT, 'src', 'CMakeLists.txt'), encoding='utf-8').read()
    return re.findall(r'^slidesim_layer\((\w+)', text, re.M)


def code_lines(text):
    """(line number, line without its comment) of a Fortran source."""
    for n, line in enumerate(text.split('\n'), 1):
        yield n, line.split('!', 1)[0]


def against_order(files, order):
    """The uses against the order in files {path: text}, path below src/."""
    layer_of = {}
    for path, text in files.items():
        for _, line in code_lines(text):
            m = DEFINES.match(line)
            if m and m.group(1).lower() != 'procedure':
                layer_of[m.group(1).lower()] = path.split('/')[0]
    found = []
    for path, text in sorted(files.items()):
        layer = path.split('/')[0]
        for n, line in code_lines(text):
            m = USES.match(line)
            if not m:
                continue
            used = m.group(1).lower()
            if used in layer_of and order.index(layer_of[used]) > order.index(layer):
                found.append(f'src/{path}:{n}: the {layer} layer uses {used} of the {layer_of[used]} layer, '
                             f'below it (the order: {", ".join(order)})')
    return found


def main():
    order = layer_order()
    made_up = {'geometry/g.f90': 'module g\n  use r_mod, only: x   ! against the order\nend module g\n',
               'rider/r.f90': 'module r_mod\n  use g\nend module r_mod\n'}
    if 'geometry' not in order or 'rider' not in order or len(against_order(made_up, order)) != 1:
        print('FAIL check_layers: the made-up use against the order (geometry using rider) was not found '
              f'exactly once; the layers read: {order}')
        return 1
    files = {}
    for path in glob.glob(os.path.join(ROOT, 'src', '**', '*.f90'), recursive=True):
        files[os.path.relpath(path, os.path.join(ROOT, 'src'))] = open(path, encoding='utf-8').read()
    unknown = sorted({p.split('/')[0] for p in files} - set(order))
    if unknown:
        print(f'FAIL check_layers: src/ folders not declared as layers in src/CMakeLists.txt: {unknown}')
        return 1
    found = against_order(files, order)
    for line in found:
        print('FAIL ' + line)
    print(f'check_layers: {len(files)} files in the layers {", ".join(order)}: {len(found)} uses against '
          'the order')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
