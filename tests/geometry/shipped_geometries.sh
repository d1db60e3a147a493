#!/usr/bin/env bash
# Every shipped geometry built through the library without io (issue 24,
# point 2) against slidesim's own result for the same input: slidesim runs
# each geometry input (the geometry scenario writes its surface grid), the
# program shipped_geometries (tests/geometry/shipped_geometries.f90, linked
# to the geometry layer only) builds the same surfaces from descriptions
# written in code and writes the same grids; every u, v, x, y, z must be the
# same number. Both build through geometry_description's build_geometry, so
# the numbers agree to the bit; any difference is a description that no
# longer says what its input says, or a reader that fills it differently.
# The inputs are those tests/library/built_through_library.txt gives to
# shipped_geometries (what check_library_coverage counts): the test fails
# when the program writes no grid for one of them, or a grid for another.
#
#     shipped_geometries.sh SLIDESIM SHIPPED_GEOMETRIES     (from the repository root)
set -u
slidesim=$1
program=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
python=python3
command -v "$python" >/dev/null || python=/usr/bin/python3
mapfile -t inputs < <("$python" -c 'import sys; sys.path.insert(0, "tests/library")
from built_inputs import inputs_of
print("\n".join(inputs_of("shipped_geometries")))')
[ "${#inputs[@]}" -gt 0 ] || { echo "FAIL no inputs given to shipped_geometries in tests/library/built_through_library.txt"; exit 1; }
for input in "${inputs[@]}"; do
  name=$(echo "${input#inputs/}" | tr '/' '_' | sed 's/\.nml$//')
  if ! "$slidesim" -q -o "$work/$name.h5" "$input" >"$work/$name.out" 2>&1; then
    echo "FAIL slidesim $input: $(cat "$work/$name.out")"
    failures=$((failures + 1))
  fi
done
"$program" "$work" || failures=$((failures + 1))
for python in python3 /usr/bin/python3; do
  if command -v "$python" >/dev/null && "$python" -c 'import h5py' 2>/dev/null; then
    "$python" - "$work" "${inputs[@]}" <<'PYEOF' || failures=$((failures + 1))
import os
import sys
import h5py
import numpy as np

work, inputs = sys.argv[1], sys.argv[2:]
failures = 0
written = {name[:-len('.txt')] for name in os.listdir(work) if name.endswith('.txt')}
names = {path[len('inputs/'):-len('.nml')].replace('/', '_'): path for path in inputs}
for name in sorted(written - set(names)):
    print(f'FAIL {name}: shipped_geometries wrote this grid, but tests/library/built_through_library.txt gives '
          f'shipped_geometries no input of that name: add the line')
    failures += 1
for path in inputs:
    name = path[len('inputs/'):-len('.nml')].replace('/', '_')
    try:
        text = open(f'{work}/{name}.txt').read().split()
    except OSError:
        print(f'FAIL {name}: shipped_geometries wrote no grid (no description of {path}?)')
        failures += 1
        continue
    n_u, n_v = int(text[0]), int(text[1])
    values = np.array([float(t) for t in text[2:]])
    u, v = values[:n_u], values[n_u:n_u + n_v]
    xyz = values[n_u + n_v:].reshape(n_u, n_v, 3)
    with h5py.File(f'{work}/{name}.h5', 'r') as f:
        g = f['/geometry/surface']
        cli = {'u': g['u'][()], 'v': g['v'][()], 'x': g['x'][()], 'y': g['y'][()], 'z': g['z'][()]}
    lib = {'u': u, 'v': v, 'x': xyz[:, :, 0], 'y': xyz[:, :, 1], 'z': xyz[:, :, 2]}
    for key in 'uvxyz':
        if cli[key].shape != lib[key].shape:
            print(f'FAIL {name} {key}: shape {lib[key].shape} built, {cli[key].shape} from slidesim')
            failures += 1
            break
        difference = np.max(np.abs(cli[key] - lib[key]))
        if not difference == 0:
            print(f'FAIL {name} {key}: differs from slidesim\'s by up to {difference:.3g}')
            failures += 1
            break
    else:
        print(f'ok   {name}: {n_u} x {n_v} grid points the same as slidesim\'s')
sys.exit(1 if failures else 0)
PYEOF
    [ "$failures" = 0 ] && echo "PASS" || echo "FAIL $failures"
    [ "$failures" = 0 ]
    exit
  fi
done
echo "FAIL no python3 with h5py (scripts/install-dependencies.sh installs python3-h5py)"
exit 1
