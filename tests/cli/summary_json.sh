#!/usr/bin/env bash
# --summary-json FILE: for every input in inputs/, the default (a ride), a run
# that failed part way and a bouncing ball (impacts) the JSON loads, has the
# keys of the printed summary with a unit for every number, and its numbers
# equal the HDF5 result's (tests/cli/check_summary_json.py); a number that
# echoes an input variable carries the unit declared for it (slidesim --input-reference); a JSON path that cannot be written is
# exit status 3. The runs come from the fixture cli_every_input
# (tests/cli/support/every_input.sh).
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
. "$root/tests/cli/support/every_input_results.sh"   # sets $results
triples=()
for name in $(cat "$results/names") stopped bouncing; do
  if [ -f "$results/$name.json" ]; then triples+=("$results/$name.json" "$results/$name.h5" "$results/$name.out")
  else echo "FAIL $name: no summary JSON"; failures=$((failures + 1)); fi
done
"$slidesim" --input-reference > "$work/reference.md" || { echo "FAIL --input-reference"; failures=$((failures + 1)); }
"$python" "$root/tests/cli/check_summary_json.py" --reference "$work/reference.md" "${triples[@]}" \
  || failures=$((failures + 1))
"$slidesim" -q -o "$work/x.h5" --summary-json "$work/no/such/folder/s.json" "$root/inputs/pendulum/simple.nml" \
  >/dev/null 2>"$work/bad.err"
got=$?
[ $got = 3 ] || { echo "FAIL unwritable summary path: exit status $got, expected 3"; failures=$((failures + 1)); }
grep -q 'no/such/folder/s.json' "$work/bad.err" || { echo "FAIL unwritable summary path not named"; failures=$((failures + 1)); }
[ "$failures" = 0 ]
