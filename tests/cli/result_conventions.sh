#!/usr/bin/env bash
# Every input in inputs/ runs, and every result file keeps the conventions and
# the layout tables of docs/outputs.md (tests/cli/check_results.py: string
# types, numeric attributes, scalar shapes, units parsed by pint, dimension
# scales, provenance, documented names/shapes/units). Uses Debian's python3
# with h5py and pint (scripts/install-dependencies.sh).
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
files=()
for input in "$root"/inputs/*.nml "$root"/inputs/*/*.nml; do
  case $input in */demo_slide/slide.nml) continue ;; esac   # a geometry file other inputs name, not a run
  name=$(echo "${input#"$root"/inputs/}" | tr '/' '_' | sed 's/\.nml$//')
  if ! (cd "$root" && "$slidesim" -q -o "$work/$name.h5" "$input" >"$work/$name.out" 2>"$work/$name.err"); then
    echo "FAIL $input: exit status non-zero: $(cat "$work/$name.err")"; failures=$((failures + 1)); continue
  fi
  files+=("$work/$name.h5")
done
# an incomplete file keeps the same conventions (the mass leaves the ellipsoid over its pole)
printf "&run output = 'stopped.h5' /\n&solver duration = 5 /\n&surface kind = 'ellipsoid', a = 1, b = 1, c = 1 /\n&point_mass v0 = 1.2, dv0 = 2.0, gravity = 0, 0, 0 /\n" >"$work/stopped.nml"
(cd "$work" && "$slidesim" -q stopped.nml >/dev/null 2>&1)
if [ -f "$work/stopped.h5" ]; then files+=("$work/stopped.h5"); else echo "FAIL stopped run: no result file"; failures=$((failures + 1)); fi
"$python" "$root/tests/cli/check_results.py" "$root/docs/outputs.md" "${files[@]}" || failures=$((failures + 1))
[ "$failures" = 0 ]
