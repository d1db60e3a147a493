#!/usr/bin/env bash
# The templates of --default-input are generated from the declarations and
# the scenario's spec (io_templates, inputs/templates/specs/): each shipped
# inputs/templates/<scenario>.nml is what slidesim prints (a declaration or a
# spec changed without regenerating them fails here, with the command that
# does), every scenario has a spec and every spec a scenario; and every
# unit and range in a comment of a declared group's variable, and every
# value, agrees with the declarations (`slidesim --input-reference`;
# tests/cli/check_template_declarations.py). A template whose comment gives
# another unit or range fails here.
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
# the shipped templates are the generated ones, one per spec, one spec per scenario
drift=0
for template in "${templates[@]}"; do
  scenario=$(basename "$template" .nml)
  [ -f "inputs/templates/specs/$scenario.spec" ] || { echo "FAIL no spec inputs/templates/specs/$scenario.spec"; drift=1; }
  if ! diff -u "inputs/templates/$scenario.nml" "$template"; then
    echo "FAIL inputs/templates/$scenario.nml differs from slidesim --default-input $scenario (above: - shipped, + generated)"
    drift=1
  fi
done
for spec in inputs/templates/specs/*.spec inputs/templates/*.nml; do
  scenario=$(basename "$spec"); scenario=${scenario%.*}
  [ -f "$work/$scenario.nml" ] || { echo "FAIL $spec: no scenario $scenario in slidesim --help"; drift=1; }
done
[ $drift = 0 ] || { echo "     regenerate them with: scripts/update_templates.sh build/slidesim"; exit 1; }
"$python" tests/cli/check_template_declarations.py "$work/reference.md" "${templates[@]}" || exit 1
# the check can fail: a template that shows another range or unit is refused
sed 's/^\(  mass = 68.5 .*! kg, \)10 \.\. 300/\110 .. 250/; s/^\(  flow_rate = 0.004 *! \)m^3\/s,/\1m\/s,/' \
  "$work/ride.nml" >"$work/wrong.nml"
grep -q '^  flow_rate = 0.004 *! m/s,' "$work/wrong.nml" && grep -q '^  mass = 68.5 .*! kg, 10 \.\. 250' "$work/wrong.nml" || {
  echo "FAIL the ride template changed: update this test's mutation"; exit 1; }
out=$("$python" tests/cli/check_template_declarations.py "$work/reference.md" "$work/wrong.nml")
echo "$out" | grep -q "mass: the comment gives the range" && echo "$out" | grep -q "flow_rate: the comment says 'm/s'" || {
  echo "FAIL a template with a wrong range and unit passed: $out"; exit 1; }
echo "${#templates[@]} templates are the generated ones and agree with the declarations"
