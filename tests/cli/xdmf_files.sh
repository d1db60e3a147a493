#!/usr/bin/env bash
# Every input in inputs/ (and the default, and a run that failed part way)
# writes an XDMF file next to its result, whose structure matches the HDF5
# file (every referenced dataset exists with the stated shape, grids and
# attributes agree), and which ParaView's XDMF reader opens showing those
# points (tests/cli/check_xdmf.py run by pvbatch, from Debian's paraview and
# python3-paraview: scripts/install-dependencies.sh). The runs come from the
# fixture cli_every_input (tests/cli/support/every_input.sh).
set -u
slidesim=$1
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
. "$root/tests/cli/support/every_input_results.sh"   # sets $results
files=()
for name in $(cat "$results/names") stopped; do
  if [ -f "$results/$name.xmf" ]; then files+=("$results/$name.xmf"); else echo "FAIL $name: no XDMF file $name.xmf"; failures=$((failures + 1)); fi
done
command -v pvbatch >/dev/null || { echo "FAIL pvbatch not found (install paraview python3-paraview)"; exit 1; }
pvbatch --force-offscreen-rendering "$root/tests/cli/check_xdmf.py" --paraview --docs "$root/docs/outputs.md" "${files[@]}" >"$work/check.out" 2>&1 \
  || failures=$((failures + 1))
grep -E '^FAIL|XDMF files checked|syntax error' "$work/check.out"
grep -q 'syntax error' "$work/check.out" && { echo "FAIL ParaView reports an expression syntax error"; failures=$((failures + 1)); }
[ "$failures" = 0 ]
