#!/usr/bin/env bash
# &rider friction (issue 24 point 3): the rider takes any friction law of the
# force-law registry, as &sled and &contact do. A ride of the demo input with
# friction = 'viscous_normal', mu = 0.05 s/m runs (exit 0) and at every
# record each contact's friction force is mu |N| |w| (w the velocity of the
# contact point, tangential: the slide is fixed), the dataset naming the law;
# it differs from the Coulomb ride (a slower exit). Bad laws are refused
# before any work (exit 1, no result file) with the group, variable, value
# and what is allowed: an unknown law, a law's parameter missing or out of
# range, another law's parameter given, mu = 0 (friction = 'none' is no
# friction), parameters with 'none'; the sweep (which varies Coulomb's mu)
# and identify_rider (which fits it) refuse another law by name.
slidesim=$1
repo=$(pwd)   # tests run from the repository root
. "$(dirname "$0")/support/checks.sh"

# the demo input with its slide's path made absolute and one change (sed)
variant() {   # source input, name, sed expression
  sed -e "$3" "$repo/inputs/$1" | sed "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" \
    >"$work/$2.nml"
}

# ---- a ride with a law whose force is proportional to |N| and the speed
variant ride/demo_slide.nml viscous "s/^  mu = 0.0724419 /  friction = 'viscous_normal', mu = 0.05 /"
(cd "$work" && "$slidesim" -q -o viscous.h5 viscous.nml >viscous.out 2>viscous.err); got=$?
check '[ $got = 0 ]' "viscous_normal ride: exit status $got ($(cat "$work/viscous.err"))"
check 'grep -q "ride ended  *end of the slide" "$work/viscous.out"' "viscous_normal ride: reaches the end"
check 'h5dump -a /rider/heels/friction_force/description "$work/viscous.h5" | grep -qF "law '"'"'viscous_normal'"'"'"' \
  "viscous_normal ride: the friction force's description names the law"
dump() { h5dump -m %.17g -y -w 0 -o "$work/$2.txt" -d "$1" "$work/viscous.h5" >/dev/null; }
for c in pelvis heels back; do
  dump /rider/$c/friction_force force; dump /rider/$c/normal_force normal; dump /rider/$c/velocity velocity
  # rtol 1e-12: the stored numbers are the law's own products, rounded once each
  check 'python3 - "$work" <<EOF
import sys
def rows(name, width):
    v = [float(x) for x in open(sys.argv[1] + "/" + name + ".txt").read().replace(",", " ").split()]
    return [v[i:i + width] for i in range(0, len(v), width)]
norm = lambda x: sum(a * a for a in x) ** 0.5
F, N, V = rows("force", 3), rows("normal", 1), rows("velocity", 3)
assert len(F) == len(N) == len(V) > 100, (len(F), len(N), len(V))
worst = max(abs(norm(f) - 0.05 * abs(n[0]) * norm(v)) / (0.05 * abs(n[0]) * norm(v)) for f, n, v in zip(F, N, V))
sys.exit(0 if worst <= 1e-12 else print("worst relative error", worst) or 1)
EOF' "viscous_normal ride: $c friction = mu |N| |w| at every record"
done
exit_speed() { grep "exit speed" "$1" | awk '{print $(NF-1)}'; }
variant ride/demo_slide.nml coulomb ""
(cd "$work" && "$slidesim" -q -o coulomb.h5 coulomb.nml >coulomb.out 2>coulomb.err); got=$?
check '[ $got = 0 ]' "coulomb ride: exit status $got ($(cat "$work/coulomb.err"))"
check 'python3 -c "import sys; sys.exit(not float(sys.argv[1]) < 0.5*float(sys.argv[2]))" \
  "$(exit_speed "$work/viscous.out")" "$(exit_speed "$work/coulomb.out")"' \
  "viscous_normal 0.05 s/m is a different ride: exit speed $(exit_speed "$work/viscous.out") m/s against \
Coulomb's $(exit_speed "$work/coulomb.out") m/s"

# ---- refusals: exit 1, no result file, the message's parts
bad() {   # name, source input, sed expression, expected message parts...
  local name=$1 source=$2 expression=$3; shift 3
  variant "$source" "$name" "$expression"
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$name.nml" >"$name.out" 2>"$name.err"); local got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1 ($(cat "$work/$name.err"))"
  for needle in "$@"; do
    check 'grep -qF -- "$needle" "$work/$name.err"' "$name: message lacks '$needle': $(cat "$work/$name.err")"
  done
  check '! ls "$work/$name".h5* >/dev/null 2>&1' "$name: a result file (or a temporary one) was written"
}
rider_mu="s/^  mu = 0.0724419 /"
bad unknown_law ride/demo_slide.nml "$rider_mu  friction = 'stiction', mu = 0.07 /" \
  "unknown_law.nml:30: &rider: friction = 'stiction' is not allowed" "none coulomb viscous viscous_weight viscous_normal"
bad law_without_parameter ride/demo_slide.nml "$rider_mu  friction = 'viscous' /" \
  "&rider: viscous_coefficient = none (not given) is not allowed" "friction = 'viscous' needs viscous_coefficient"
bad other_law_parameter ride/demo_slide.nml "$rider_mu  friction = 'viscous', viscous_coefficient = 30, mu = 0.07 /" \
  "other_law_parameter.nml:30: &rider: mu = 0.07 is not allowed: friction = 'viscous' does not use it"
bad mu_zero ride/demo_slide.nml "$rider_mu  mu = 0 /" "mu_zero.nml:30: &rider: mu = 0 is not allowed" "> 0 and <= 10"
bad none_with_mu ride/demo_slide.nml "$rider_mu  friction = 'none', mu = 0.07 /" \
  "&rider: mu = 0.07 is not allowed: friction = 'none' has no parameters"
bad regularization ride/demo_slide.nml "$rider_mu  mu = 0.07, regularization_speed = 0 /" \
  "&rider: regularization_speed = 0 is not allowed"
bad sweep_law sweep/demo_population.nml "s/com_height = 0.075, mu = 0.0724419/com_height = 0.075, friction = 'viscous_normal', mu = 0.05/" \
  "sweep_law.nml:32: &rider: friction = 'viscous_normal' is not allowed: the sweep varies and records the rider's Coulomb mu" \
  "allowed: 'coulomb', 'none'"
cp "$repo"/inputs/design/rider_*.csv "$work/"
bad identify_law design/identify_rider_demo.nml "s/^  mu = 0.036/  friction = 'none'/" \
  "identify_law.nml:26: &rider: friction = 'none' is not allowed: identify_rider fits the Coulomb mu_D" \
  "allowed: 'coulomb'"

echo "rider_friction: $checks checks, $failures failed"
[ "$failures" = 0 ]
