#!/usr/bin/env bash
# Bad input stops before any work: exit status non-zero, a message that names the
# file, the group, the variable, the value and what is allowed, no result file.
set -u
slidesim=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0; checks=0; nan_cases=0

# expect NAME STATUS NEEDLE... : runs $work/NAME.nml, checks the exit status, that
# every needle appears in the message, and that no result file was left.
expect() {
  local name=$1 want=$2; shift 2
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$name.nml" >"$name.out" 2>"$name.err")
  local got=$?
  local ok=1
  if [ "$got" != "$want" ]; then
    echo "FAIL $name: exit status $got, expected $want"; ok=0
  fi
  for needle in "$@"; do
    grep -qF -- "$needle" "$work/$name.err" || { echo "FAIL $name: message lacks '$needle'"; ok=0; }
  done
  if ls "$work"/*.h5 "$work"/*.h5.tmp >/dev/null 2>&1; then
    echo "FAIL $name: a result file was left behind: $(ls "$work"/*.h5*)"; ok=0
    rm -f "$work"/*.h5 "$work"/*.h5.tmp
  fi
  if [ $ok = 0 ]; then failures=$((failures + 1)); echo "  message: $(cat "$work/$name.err")"; fi
}

base_surface="&surface kind = 'ellipsoid', a = 2, b = 1.5, c = 1 /"
base_mass="&point_mass v0 = -0.5, du0 = 1 /"

printf "&run scenario = 'point_mass', output = 'x.h5' /\n&surface kind = 'plane', height = 1 /\n" > "$work/unknown_variable.nml"
expect unknown_variable 1 unknown_variable.nml '&surface' height 'allowed:' point_a

printf "&run scenario = 'point_mas', output = 'x.h5' /\n" > "$work/misspelt_scenario.nml"
expect misspelt_scenario 1 misspelt_scenario.nml '&run' scenario "'point_mas'" point_mass

printf "&run output = 'x.h5' /\n&surface kind = 'ellipsoid', a = -1.5 /\n%s\n" "$base_mass" > "$work/negative_axis.nml"
expect negative_axis 1 negative_axis.nml:2 '&surface' 'a = -1.5' 'in [0.001, 10000] (m)'

printf "&run output = 'x.h5' /\n%s\n&point_mass u0 = NaN /\n" "$base_surface" > "$work/not_finite.nml"
expect not_finite 1 not_finite.nml '&point_mass' 'u0 = NaN' finite

printf "&run output = 'x.h5' /\n%s\n%s\n&solver rtol = -1 /\n" "$base_surface" "$base_mass" > "$work/bad_tolerance.nml"
expect bad_tolerance 1 bad_tolerance.nml:4 '&solver' 'rtol = -1' 'must be a finite number in'

printf "&run output = 'x.h5' /\n&surface kind = 'torus' /\n" > "$work/unknown_kind.nml"
expect unknown_kind 1 unknown_kind.nml '&surface' kind "'torus'" elliptic_cylinder

printf "&run output = 'x.h5' /\n&surfce kind = 'plane' /\n" > "$work/unknown_group.nml"
expect unknown_group 1 unknown_group.nml '&surfce' '&surface'

printf "&run output = 'x.h5' /\n&surface kind = 'ellipsoid' /\n&point_mass v0 = 2.0 /\n" > "$work/outside_domain.nml"
expect outside_domain 1 outside_domain.nml '&point_mass' 'u0, v0' 'parameter domain'

printf "&run output = '%s/no/such/folder/x.h5' /\n%s\n%s\n" "$work" "$base_surface" "$base_mass" > "$work/unwritable.nml"
expect unwritable 3 unwritable.nml:1 '&run' 'output' 'no/such/folder/x.h5' 'cannot write the result file: No such file or directory'

mkdir -p "$work/a_folder"
printf "&run output = 'a_folder' /\n%s\n%s\n" "$base_surface" "$base_mass" > "$work/folder_output.nml"
expect folder_output 3 folder_output.nml:1 '&run' output a_folder 'is a folder'

: > "$work/empty.nml"
expect empty 1 empty.nml 'is empty'

printf "&surface kind = 'plane' /\n" > "$work/no_run.nml"
expect no_run 1 no_run.nml 'no &run group'

printf "&run output = 'x.h5' /\n%s\n%s\n&point_mass mass = 2 /\n" "$base_surface" "$base_mass" > "$work/repeated.nml"
expect repeated 1 repeated.nml '&point_mass' 'more than once'

printf "&run output = 'x.h5' /\n&surface kind = 'ellipsoid', a = 'two' /\n" > "$work/wrong_type.nml"
expect wrong_type 1 wrong_type.nml:2 '&surface' "a = 'two' is not allowed" 'must be a finite number'

for bad in "mass = NaN" "friction_coefficient = -Inf" "gravity = 0, NaN, 0"; do
  name=nan_$((++nan_cases))
  printf "&run output = 'x.h5' /\n%s\n&point_mass %s /\n" "$base_surface" "$bad" > "$work/$name.nml"
  expect $name 1 $name.nml '&point_mass' "${bad%% =*}"
done
printf "&run output = 'x.h5' /\n%s\n%s\n&solver rtol = NaN /\n" "$base_surface" "$base_mass" > "$work/nan_rtol.nml"
expect nan_rtol 1 nan_rtol.nml '&solver' 'rtol = NaN'

checks=$((checks + 1))
(cd "$work" && "$slidesim" missing.nml >/dev/null 2>"$work/missing.err"); got=$?
if [ $got = 0 ] || ! grep -qF missing.nml "$work/missing.err"; then
  echo "FAIL missing file: exit $got, message: $(cat "$work/missing.err")"; failures=$((failures + 1))
fi

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
