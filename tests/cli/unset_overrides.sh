#!/usr/bin/env bash
# --unset group%variable removes a variable from the input (issue 27, point
# 7): it takes its default, so a friction input can be made frictionless;
# checked like --set (an unknown variable or group refused, a repeated group
# addressed as group(k)% or group(name)%), kept with the overrides in the
# result file.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

coulomb="$root/inputs/point_mass/plane_coulomb.nml"
paraboloids="$root/inputs/contact/paraboloids.nml"
# cmd NAME WANT NEEDLE... -- ARGS...: runs slidesim -q ARGS in $work, checks
# the exit status and every needle on stderr
cmd() {
  local name=$1 want=$2; shift 2
  local needles=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do needles+=("$1"); shift; done
  shift
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$@" > "$name.out" 2> "$name.err" < /dev/null); local got=$?
  [ "$got" = "$want" ] || fail "$name: exit status $got, expected $want: $(head -c 400 "$work/$name.err")"
  for needle in "${needles[@]}"; do
    grep -qF -- "$needle" "$work/$name.err" || fail "$name: message lacks '$needle': $(head -c 400 "$work/$name.err")"
  done
}

# the block on the 30 degree plane without its Coulomb friction: the speed
# after 3 s is the frictionless v0 + g sin(30 deg) t = 0.5 + 9.80665/2*3 m/s
# (with mu = 0.2 it would be 10.11 m/s); rtol 1e-10 of the integrator, 1e-8 here
cmd frictionless 0 -- --unset point_mass%friction --unset point_mass%friction_coefficient \
  --summary-json frictionless.json -o frictionless.h5 "$coulomb"
if [ -n "$h5python" ] && [ -f "$work/frictionless.json" ]; then
  "$h5python" - "$work/frictionless.json" "$work/frictionless.h5" <<'PY' || fail "frictionless: see above"
import json, sys, h5py
v = json.load(open(sys.argv[1]))['values']['final_speed']
want = 0.5 + 9.80665 / 2 * 3
if abs(v - want) > 1e-8 * want:
    sys.exit(f'final speed {v} m/s, frictionless {want} m/s')
with h5py.File(sys.argv[2]) as f:
    text = f['/input/namelist'].asstr()[()]
for line in ['! --unset point_mass%friction', '! --unset point_mass%friction_coefficient']:
    if line not in text:
        sys.exit(f'the stored input lacks "{line}"')
PY
fi
# only the friction law removed: its mu is refused as a value the law does not use
cmd law_only 1 'friction_coefficient' -- --check --unset point_mass%friction "$coulomb"
# a variable the input does not give: its default already, fine
cmd not_given 0 -- --check --unset point_mass%dv0 "$coulomb"
# unknown variable (given or not) and unknown group: refused, naming the argument
cmd unknown_variable 1 '--unset point_mass%frictio: &point_mass: unknown variable "frictio"' -- \
  --check --unset point_mass%frictio "$coulomb"
cmd unknown_group 1 '--unset pointmass%friction: the input has no &pointmass group' -- \
  --check --unset pointmass%friction "$coulomb"
cmd subscript 1 '--unset point_mass%gravity(3): "gravity(3)" is not a variable name' -- \
  --check --unset 'point_mass%gravity(3)' "$coulomb"
cmd no_variable 1 '--unset point_mass: write --unset group%variable' -- --check --unset point_mass "$coulomb"
# a repeated group: say which, as with --set
cmd which 1 '--unset body%mass: the input has 2 &body groups' '--unset "body(2)%mass"' -- \
  --check --unset body%mass "$paraboloids"
cmd by_name 1 '--unset body(paraboloid_3)%mas: &body: unknown variable "mas"' -- \
  --check --unset 'body(paraboloid_3)%mas' "$paraboloids"
cmd by_index 0 -- --check --unset 'body(2)%mass' "$paraboloids"
# applied in order with --set: the later one wins
cmd set_after 1 'friction_coefficient = 50' -- --check --unset point_mass%friction_coefficient \
  --set point_mass%friction_coefficient=5 --set point_mass%friction_coefficient=50 "$coulomb"

finish
