#!/usr/bin/env bash
# Every input in inputs/ runs, and every result file (also one of a run that
# failed part way, and a bouncing ball's: a flight with impacts) keeps the
# conventions and the layout tables of docs/outputs.md
# (tests/cli/check_results.py: string types, numeric attributes, scalar
# shapes, units parsed by pint and UDUNITS-2, dimension scales, provenance,
# documented names/shapes/units). The runs come from the fixture
# cli_every_input (tests/cli/support/every_input.sh). Uses Debian's python3
# with h5py and pint (scripts/install-dependencies.sh).
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
. "$root/tests/cli/support/every_input_results.sh"   # sets $results
files=()
for name in $(cat "$results/names") stopped bouncing; do
  if [ -f "$results/$name.h5" ]; then files+=("$results/$name.h5"); else echo "FAIL $name: no result file"; failures=$((failures + 1)); fi
done
"$python" "$root/tests/cli/check_results.py" "$root/docs/outputs.md" "${files[@]}" || failures=$((failures + 1))
[ "$failures" = 0 ]
