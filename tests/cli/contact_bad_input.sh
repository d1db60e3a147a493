#!/usr/bin/env bash
# Bad contact inputs stop before any work (exit 1, no result file) with a
# message naming the file, the group (with its line), the variable, the value
# and what is allowed: unknown names, a contact listed before the one that
# carries its body_1, a body carried twice or never, a loop that cannot close
# (which contact, by how much), sides that point the normals the same way
# (which contact, which side to flip), inertia tensors that are not positive
# definite (at the &body), start velocities that push into the surface; a
# chain that does not apply (the open chain with rolling, a chain at velocity
# level) or is unknown; a friction law without mu; what several bodies in
# flight cannot do yet (one closed beside a flight, a contact between two
# bodies that may open with a level or a chain). A message about a contact
# or body names it once, by its place.
set -u
slidesim=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0; checks=0

expect() {
  local name=$1 want=$2; shift 2
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$name.nml" >"$name.out" 2>"$name.err")
  local got=$?
  local ok=1
  [ "$got" = "$want" ] || { echo "FAIL $name: exit status $got, expected $want"; ok=0; }
  for needle in "$@"; do
    grep -qF -- "$needle" "$work/$name.err" || { echo "FAIL $name: message lacks '$needle'"; ok=0; }
  done
  if ls "$work"/*.h5 "$work"/*.tmp >/dev/null 2>&1; then
    echo "FAIL $name: a result file was left behind"; ok=0; rm -f "$work"/*.h5 "$work"/*.tmp
  fi
  [ -n "${SHOW:-}" ] && echo "$name: $(cat "$work/$name.err")"
  if [ $ok = 0 ]; then failures=$((failures + 1)); echo "  message: $(cat "$work/$name.err")"; fi
}

head="&run scenario = 'contact', output = 'x.h5' /
&solver duration = 0.1, output_step = 0.01 /
&shape name = 'table', kind = 'plane' /
&shape name = 'ball', kind = 'ellipsoid', a = 0.1, b = 0.1, c = 0.1 /"
ball="&body name = 'ball', mass = 1, solid_of = 'ball', position = 0, 0, 0.2, angles_deg = 90, 0, 0 /"

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'tabel', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" "$ball" > "$work/unknown_shape.nml"
expect unknown_shape 1 'unknown_shape.nml:' '&contact' shape_1 "'tabel'" "the shapes are 'table', 'ball'"

printf "%s\n&body name = 'ball', mass = 1, solid_of = 'bal', position = 0, 0, 0.2 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" > "$work/unknown_solid.nml"
expect unknown_solid 1 'unknown_solid.nml:' '&body' solid_of "'bal'" "the shapes are 'table', 'ball'"

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'bal', shape_2 = 'ball' /\n" \
  "$head" "$ball" > "$work/unknown_body.nml"
expect unknown_body 1 'unknown_body.nml:' '&contact' body_2 "'bal'" "'ball'"

printf "%s\n%s\n&body name = 'top', mass = 1, solid_of = 'ball', position = 0, 0, 0.4 /\n&contact name = 'c2', body_1 = 'ball', shape_1 = 'ball', body_2 = 'top', shape_2 = 'ball' /\n&contact name = 'c1', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" "$ball" > "$work/order.nml"
expect order 1 'order.nml:7:' "&contact name = 'c2'" "body_1 = 'ball'" 'not placed yet' 'before'

printf "%s\n%s\n&body name = 'lost', mass = 1, solid_of = 'ball', position = 1, 0, 0.2 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" "$ball" > "$work/not_carried.nml"
expect not_carried 1 'not_carried.nml' "body 'lost'" 'not body_2 of any contact'

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', side_2 = -1 /\n" \
  "$head" "$ball" > "$work/parallel.nml"
expect parallel 1 'parallel.nml:' "&contact name = 'c'" 'side_1 = +1 and side_2 = -1' 'same way' 'parallel normals' \
  'flip side_2 (side_2 = +1)'
grep -q 'loop' "$work/parallel.err" && { echo "FAIL parallel: an open chain's message speaks of a loop"; failures=$((failures + 1)); }

printf "%s\n&body name = 'ball', mass = 1, solid_of = 'ball', position = 0, 0, 0.2, angles_deg = 90, 0, 0, velocity = 0, 0, -1 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" > "$work/into_surface.nml"
expect into_surface 1 'into_surface.nml' 'not consistent with the contacts' "body 'ball'" "contact 'c'"

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', rolling = .true., friction = 'coulomb', mu = 0.5 /\n" \
  "$head" "$ball" > "$work/rolling_friction.nml"
expect rolling_friction 1 'rolling_friction.nml:' '&contact' friction "'coulomb'" 'no-slip'

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', mu = 0.3 /\n" \
  "$head" "$ball" > "$work/unused_mu.nml"
expect unused_mu 1 'unused_mu.nml:' '&contact' mu "friction = 'none'"

# a friction law without mu would run frictionless (mu = 0): refused
for law in viscous_weight viscous_normal coulomb; do
  printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', friction = '$law' /\n" \
    "$head" "$ball" > "$work/no_mu_$law.nml"
  expect "no_mu_$law" 1 "no_mu_$law.nml:" '&contact' 'mu = none' "friction = '$law' needs mu" '> 0 and <='
done

printf "%s\n&body name = 'ball', mass = 1, position = 0, 0, 0.2 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" > "$work/no_inertia.nml"
expect no_inertia 1 'no_inertia.nml:' '&body' inertia solid_of

# inertia tensors that are not positive definite: refused at the &body
printf "%s\n&body name = 'ball', mass = 1, inertia = 0, 0, 0, position = 0, 0, 0.2 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" > "$work/zero_inertia.nml"
expect zero_inertia 1 'zero_inertia.nml:5:' '&body' 'inertia = [0.0, 0.0, 0.0]' "body 'ball'" 'positive definite'
printf "%s\n&body name = 'ball', mass = 1, inertia = 1e-5, 1e-5, 1e-5, products = 1e-4, 0, 0, position = 0, 0, 0.2 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" > "$work/indefinite.nml"
expect indefinite 1 'indefinite.nml:5:' '&body' 'products = [1.0E-04, 0.0, 0.0]' "body 'ball'" 'positive definite'

# a body carried twice by the same shapes: its second contact (a closure
# loop, contact_loops) takes no degree of freedom of its own
printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n&contact name = 'again', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
  "$head" "$ball" > "$work/twice.nml"
expect twice 1 'twice.nml:7:' "&contact name = 'again': no coordinate of the contact that carries its body moves it along its normal" 'several closed contacts of one body must each take a degree of freedom of its own'

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', rolling = .true., chain = 'open' /\n" \
  "$head" "$ball" > "$work/open_rolling.nml"
expect open_rolling 1 'open_rolling.nml:' '&contact' chain "'open'" 'rolling contact needs the loop'

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', level = 'velocity', chain = 'loop' /\n" \
  "$head" "$ball" > "$work/chain_velocity.nml"
expect chain_velocity 1 'chain_velocity.nml:' '&contact' chain "'loop'" "level = 'position' only"

printf "%s\n%s\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', chain = 'closed' /\n" \
  "$head" "$ball" > "$work/unknown_chain.nml"
expect unknown_chain 1 'unknown_chain.nml:' '&contact' chain "'closed'" 'open loop'

# several bodies (issue 25): each carried by its closed contacts or flying,
# so a body with two contacts that start closed on the same shapes among
# several bodies (no degree of freedom for the second) is refused naming the
# input, and so are a contact between two bodies that opens and closes at
# velocity level, or with a chain (it closes by the open chain, sliding, or
# by the loop, rolling)
printf "%s\n%s\n&body name = 'other', mass = 1, solid_of = 'ball', position = 1, 0, 0.5 /\n&contact name = 'c', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n&contact name = 'c2', shape_1 = 'table', body_2 = 'other', shape_2 = 'ball', start = 'open', restitution = 0.5 /\n&contact name = 'c3', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', may_open = .true. /\n" \
  "$head" "$ball" > "$work/two_closed.nml"
expect two_closed 1 'two_closed.nml:9:' "&contact name = 'c3'" 'no coordinate of the contact that carries its body moves it along its normal'
printf "%s\n%s\n&body name = 'top', mass = 1, solid_of = 'ball', position = 0, 0, 0.4 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n&contact name = 'stack', body_1 = 'ball', shape_1 = 'ball', body_2 = 'top', shape_2 = 'ball', may_open = .true., level = 'velocity' /\n" \
  "$head" "$ball" > "$work/top_velocity.nml"
expect top_velocity 1 'top_velocity.nml:8:' "&contact name = 'stack'" "body_1 = 'ball'" \
  'a contact between two bodies closes at position level, sliding by the open chain or rolling by the loop' \
  'leave them out'
printf "%s\n%s\n&body name = 'top', mass = 1, solid_of = 'ball', position = 0, 0, 0.6 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball', start = 'open', restitution = 0.5 /\n&contact name = 'hit', body_1 = 'ball', shape_1 = 'ball', body_2 = 'top', shape_2 = 'ball', start = 'open', restitution = 0.5, friction = 'coulomb', mu = 0.3, chain = 'open' /\n" \
  "$head" "$ball" > "$work/pair_chain.nml"
expect pair_chain 1 'pair_chain.nml:8:' "&contact name = 'hit'" '(level and chain there are not built)' \
  'leave them out'

# a cup that cannot close in a B-spline bowl (table 3.2's paraboloids): which
# contact, by how much
grid() {   # grid HALF_WIDTH A2: 13 x 13 points of z = (x^2 + y^2)/A2
  echo "x, y, z"
  for i in $(seq 0 12); do for j in $(seq 0 12); do
    echo "$1 $2 $i $j" | awk '{x = -$1 + 2*$1*$3/12; y = -$1 + 2*$1*$4/12; printf "%.17g, %.17g, %.17g\n", x, y, (x*x + y*y)/$2}'
  done; done
}
grid 2 3 > "$work/bowl.csv"
grid 0.5 0.5 > "$work/cup.csv"
printf "&bspline file = 'bowl.csv', degree = 5, smoothing = 0.05 /\n" > "$work/bowl.geo"
printf "&bspline file = 'cup.csv', degree = 5, smoothing = 0.05 /\n" > "$work/cup.geo"
printf "&run scenario = 'contact', output = 'x.h5' /\n&shape name = 'bowl', kind = 'bspline', geometry_file = 'bowl.geo' /\n&shape name = 'cup', kind = 'bspline', geometry_file = 'cup.geo' /\n&body name = 'cup', mass = 1, inertia = 0.1, 0.1, 0.1, position = 1.74, 0, 1.3, angles_deg = 0, -11.459156, 0 /\n&contact name = 'cup_in_bowl', body_1 = 'ground', shape_1 = 'bowl', body_2 = 'cup', shape_2 = 'cup', side_2 = -1 /\n" > "$work/no_closure.nml"
expect no_closure 1 'no_closure.nml' "loop 'cup_in_bowl'" 'off by'

echo "contact_bad_input: $checks checks, $failures failed"
[ "$failures" = 0 ]
