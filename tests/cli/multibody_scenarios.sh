#!/usr/bin/env bash
# The multibody scenarios end to end: every input in inputs/pendulum, fourbar,
# sled runs (exit 0) and writes a result file with units on its datasets; the
# sled run past the end of the demo slide ends complete with 'end of slide'; bad
# input stops with a message naming the group/variable or the loop, exit 1, no
# result file.
set -u
slidesim=$1
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0; checks=0

for input in "$root"/inputs/pendulum/*.nml "$root"/inputs/fourbar/*.nml "$root"/inputs/sled/*.nml; do
  name=$(basename "$input" .nml)
  checks=$((checks + 1))
  # from the repository root: inputs may name other files relative to it
  if ! (cd "$root" && "$slidesim" -q -o "$work/$name.h5" "$input" >"$work/$name.out" 2>"$work/$name.err"); then
    echo "FAIL $input: exit status non-zero: $(cat "$work/$name.err")"; failures=$((failures + 1)); continue
  fi
  scenario=$(h5dump -a /scenario "$work/$name.h5" 2>/dev/null | grep -o '"[a-z_]*"' | tr -d '"' | tail -1)
  if ! h5dump -a "/$scenario/energy/units" "$work/$name.h5" >/dev/null 2>&1; then
    echo "FAIL $input: /$scenario/energy has no units attribute"; failures=$((failures + 1))
  fi
done

# the sled down the whole demo slide: the end of the slide is a normal end
checks=$((checks + 1))
sed "s/duration = 8.0/duration = 60.0/; s#'../demo_slide/slide.nml'#'$root/inputs/demo_slide/slide.nml'#" \
  "$root/inputs/sled/demo_slide.nml" > "$work/end_of_slide.nml"
if "$slidesim" -q -o "$work/end.h5" "$work/end_of_slide.nml" >"$work/end.out" 2>"$work/end.err"; then
  status=$(h5dump -a /status "$work/end.h5" 2>/dev/null | grep -o '"[a-z]*"' | tail -1)
  outcome=$(h5dump -a /sled/outcome "$work/end.h5" 2>/dev/null)
  if [ "$status" != '"complete"' ] || ! echo "$outcome" | grep -q 'end of slide'; then
    echo "FAIL end of slide: status $status, outcome $outcome"; failures=$((failures + 1))
  fi
else
  echo "FAIL end of slide: exit status non-zero: $(cat "$work/end.err")"; failures=$((failures + 1))
fi

expect() {
  local name=$1; shift
  checks=$((checks + 1))
  (cd "$work/bad" && "$slidesim" -q "$name.nml" >"$name.out" 2>"$name.err")
  local got=$? ok=1
  [ "$got" = 1 ] || { echo "FAIL $name: exit status $got, expected 1"; ok=0; }
  for needle in "$@"; do
    grep -qF -- "$needle" "$work/bad/$name.err" || { echo "FAIL $name: message lacks '$needle'"; ok=0; }
  done
  if ls "$work"/bad/*.h5 >/dev/null 2>&1; then echo "FAIL $name: result file left behind"; ok=0; rm -f "$work"/bad/*.h5; fi
  if [ $ok = 0 ]; then failures=$((failures + 1)); echo "  message: $(cat "$work/bad/$name.err")"; fi
}
mkdir -p "$work/bad"
printf "&run scenario = 'pendulum', output = 'x.h5' /\n&pendulum links = 3 /\n" > "$work/bad/links.nml"
expect links links.nml '&pendulum' 'links = 3' 'must be a whole number in [1, 2]'
printf "&run scenario = 'pendulum', output = 'x.h5' /\n&pendulum mass = 0 /\n" > "$work/bad/massless.nml"
expect massless '&pendulum' 'mass(1) = 0' 'in [1.0E-06, 1000000] (kg)'
printf "&run scenario = 'fourbar', output = 'x.h5' /\n&fourbar b = 0.2, c = 0.2 /\n" > "$work/bad/open_loop.nml"
expect open_loop '&fourbar' coupler-rocker 'cannot be assembled'
printf "&run scenario = 'sled', output = 'x.h5' /\n&sled inertia = 1, 0.1, 0.1 /\n" > "$work/bad/inertia.nml"
expect inertia '&sled' inertia 'sum of the other two'
printf "&run scenario = 'sled', output = 'x.h5' /\n&surface kind = 'ellipsoid', a = 1, b = 1, c = 1 /\n&sled v0 = 3 /\n" > "$work/bad/domain.nml"
expect domain '&sled' 'u0, v0' 'parameter domain'

echo "multibody_scenarios: $checks checks, $failures failed"
[ "$failures" = 0 ]
