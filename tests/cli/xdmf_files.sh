#!/usr/bin/env bash
# Every input in inputs/ writes an XDMF file next to its result, whose
# structure matches the HDF5 file (every referenced dataset exists with the
# stated shape, grids and attributes agree), and which ParaView's XDMF reader
# opens showing those points (tests/cli/check_xdmf.py run by pvbatch, from
# Debian's paraview and python3-paraview: scripts/install-dependencies.sh).
set -u
slidesim=$1
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for input in "$root"/inputs/*.nml "$root"/inputs/*/*.nml; do
  case $input in */demo_slide/slide.nml) continue ;; esac   # a geometry file other inputs name, not a run
  name=$(echo "${input#"$root"/inputs/}" | tr '/' '_' | sed 's/\.nml$//')
  if ! (cd "$root" && "$slidesim" -q -o "$work/$name.h5" "$input" >/dev/null 2>"$work/$name.err"); then
    echo "FAIL $input: exit status non-zero: $(cat "$work/$name.err")"; failures=$((failures + 1)); continue
  fi
  [ -f "$work/$name.xmf" ] || { echo "FAIL $input: no XDMF file $name.xmf"; failures=$((failures + 1)); }
done
# an incomplete run keeps its XDMF file too (the mass leaves the ellipsoid over its pole)
printf "&run output = 'stopped.h5' /\n&solver duration = 5 /\n&surface kind = 'ellipsoid', a = 1, b = 1, c = 1 /\n&point_mass v0 = 1.2, dv0 = 2.0, gravity = 0, 0, 0 /\n" >"$work/stopped.nml"
(cd "$work" && "$slidesim" -q stopped.nml >/dev/null 2>&1)
[ -f "$work/stopped.xmf" ] || { echo "FAIL stopped run: no XDMF file"; failures=$((failures + 1)); }
command -v pvbatch >/dev/null || { echo "FAIL pvbatch not found (install paraview python3-paraview)"; exit 1; }
pvbatch --force-offscreen-rendering "$root/tests/cli/check_xdmf.py" --paraview "$work"/*.xmf >"$work/check.out" 2>&1 \
  || failures=$((failures + 1))
grep -E '^FAIL|XDMF files checked|syntax error' "$work/check.out"
grep -q 'syntax error' "$work/check.out" && { echo "FAIL ParaView reports an expression syntax error"; failures=$((failures + 1)); }
[ "$failures" = 0 ]
