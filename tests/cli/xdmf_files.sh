#!/usr/bin/env bash
# Every input in inputs/ (and the default, a run that failed part way and a
# bouncing ball: a flight with impacts)
# writes an XDMF file next to its result, whose structure holds (every array a
# dataset of the result beside it, by its file name, that exists with as many
# values as the DataItem states; inline DataItems as many numbers as they
# state; grids and attributes agree, a surface grid and the water band equal
# the result's), and which ParaView opens with the
# reader it picks by itself (OpenDataFile, as File > Open: Xdmf3ReaderS),
# without a crash, showing the file's time steps, arrays and points
# (tests/cli/check_xdmf.py run by pvpython, from Debian's paraview and
# python3-paraview: scripts/install-dependencies.sh). The runs come from the
# fixture cli_every_input (tests/cli/support/every_input.sh). The macro
# scripts/paraview_open.py builds its pipeline for the default ride (no display).
set -u
slidesim=$1
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
. "$root/tests/cli/support/every_input_results.sh"   # sets $results
files=()
for name in $(cat "$results/names") stopped bouncing; do
  if [ -f "$results/$name.xmf" ]; then files+=("$results/$name.xmf"); else echo "FAIL $name: no XDMF file $name.xmf"; failures=$((failures + 1)); fi
done
command -v pvpython >/dev/null || { echo "FAIL pvpython not found (install paraview python3-paraview)"; exit 1; }
# each file opened from its own folder as ./NAME.xmf (docs/outputs.md: the
# Xdmf3 readers resolve the result file against the folder the .xmf is named
# with, and abort on a bare name); its arrays are read from NAME.h5 beside it
names=("${files[@]##*/}")
(cd "$results" && pvpython "$root/tests/cli/check_xdmf.py" --paraview --docs "$root/docs/outputs.md" \
   "${names[@]/#/./}") >"$work/check.out" 2>&1
rc=$?
[ "$rc" = 0 ] || failures=$((failures + 1))
grep -E '^FAIL|XDMF files checked|SIGABRT|SIGSEGV|terminate called' "$work/check.out"
grep -q 'XDMF files checked' "$work/check.out" || echo "FAIL ParaView stopped before the end (exit status $rc)"
# the macro that opens a ride ready to play builds its pipeline (no display here)
(cd "$results" && pvpython "$root/scripts/paraview_open.py" --no-render default.xmf) >"$work/macro.out" 2>&1
for grid in 'slide surface: 19200 points' 'water band: ' 'rider legs: 8 points' 'rider trunk: 8 points' 'pelvis path: '; do
  grep -q "^$grid" "$work/macro.out" || { echo "FAIL scripts/paraview_open.py: no '$grid' in: $(grep -v '^ *[0-9]* *0x' "$work/macro.out" | tail -5)"; failures=$((failures + 1)); }
done
[ "$failures" = 0 ]
