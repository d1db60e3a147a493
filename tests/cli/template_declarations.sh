#!/usr/bin/env bash
# The templates of --default-input show the units and ranges the readers
# check: every unit and range in a comment of a declared group's variable,
# and every value, agrees with the declarations (`slidesim
# --input-reference`; tests/cli/check_template_declarations.py). A template
# whose comment gives another unit or range fails here.
set -u
slidesim=$1
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$slidesim" --input-reference >"$work/reference.md" || { echo "FAIL slidesim --input-reference"; exit 1; }
templates=()
for scenario in $("$slidesim" --help | awk '/^scenarios:/ { on = 1; next } on && NF == 0 { exit } on { print $1 }'); do
  "$slidesim" --default-input "$scenario" >"$work/$scenario.nml" || { echo "FAIL --default-input $scenario"; exit 1; }
  templates+=("$work/$scenario.nml")
done
[ ${#templates[@]} -ge 10 ] || { echo "FAIL only ${#templates[@]} templates found in slidesim --help"; exit 1; }
"$python" tests/cli/check_template_declarations.py "$work/reference.md" "${templates[@]}" || exit 1
# the check can fail: a template that shows another range or unit is refused
sed 's/! kg, 10 \.\. 300/! kg, 10 .. 250/; s/flow_rate = 0.004                ! m^3\/s/flow_rate = 0.004  ! l\/s/' \
  "$work/ride.nml" >"$work/wrong.nml"
grep -q 'flow_rate = 0.004  ! l/s' "$work/wrong.nml" && grep -q '10 \.\. 250' "$work/wrong.nml" || {
  echo "FAIL the ride template changed: update this test's mutation"; exit 1; }
sed -i 's|! l/s|! m/s|' "$work/wrong.nml"
out=$("$python" tests/cli/check_template_declarations.py "$work/reference.md" "$work/wrong.nml")
echo "$out" | grep -q "mass: the comment gives the range" && echo "$out" | grep -q "flow_rate: the comment says 'm/s'" || {
  echo "FAIL a template with a wrong range and unit passed: $out"; exit 1; }
echo "${#templates[@]} templates agree with the declarations"
