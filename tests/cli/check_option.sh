#!/usr/bin/env bash
# --check (issue 13, item 4) reads the input and builds the models of every
# scenario without running them: every shipped input passes quickly and
# writes nothing; inputs that only the model build can refuse (a loop that
# cannot close, a rider whose heels miss the slide, a contact that does not
# press, a tube that folds ...) are refused by --check as by the run (exit 1,
# the message, no file). The mutation test checks the same on a few hundred
# mutants: no run refuses what --check passed.
set -u
slidesim=$1
root=$(pwd)
extra_args=--check
. "$(dirname "$0")/support/cli_checks.sh"

# every shipped input, each scenario: input ok, nothing written
seen=""
while IFS= read -r input; do
  case $input in "$root"/inputs/templates/*) continue ;; esac   # not */templates/*: the checkout may be in one
  checks=$((checks + 1))
  name=$(basename "$input" .nml)
  out=$(cd "$(dirname "$input")" && "$slidesim" --check -o "$work/checked_$name.h5" "$(basename "$input")" 2>&1)
  got=$?
  [ $got = 0 ] || { fail "--check $input: exit $got: $out"; continue; }
  scenario=$(echo "$out" | sed -n 's/.*input ok (scenario \([a-z_]*\);.*/\1/p')
  [ -n "$scenario" ] || fail "--check $input: no 'input ok (scenario ...': $out"
  seen="$seen $scenario"
  ls "$work/checked_$name".* >/dev/null 2>&1 && fail "--check $input: wrote $(ls "$work/checked_$name".*)"
done < <(grep -l "^ *scenario = " -r "$root/inputs" --include='*.nml' | sort)
for scenario in $("$slidesim" --help | awk '/^scenarios:/ {on = 1; next} on && NF == 0 {exit} on {print $1}'); do
  checks=$((checks + 1))
  case " $seen " in *" $scenario "*) ;; *) fail "no shipped input of scenario $scenario was checked" ;; esac
done

# refused only once the models are built: --check refuses them (run_case
# runs with --check here, and checks exit 1, the message, no file)
printf "&run scenario = 'fourbar', output = 'open_loop.h5' /\n&fourbar b = 0.2, c = 0.2 /\n" > "$work/open_loop.nml"
run_case open_loop 1 'open_loop.nml' '&fourbar' 'cannot be assembled'
printf "&run scenario = 'sled', output = 'sled_domain.h5' /\n&surface kind = 'ellipsoid', a = 1, b = 1, c = 1 /\n&sled v0 = 3 /\n" > "$work/sled_domain.nml"
run_case sled_domain 1 'sled_domain.nml' '&sled' 'parameter domain'
printf "&run output = 'pm_domain.h5' /\n&surface kind = 'ellipsoid' /\n&point_mass v0 = 2.0 /\n" > "$work/pm_domain.nml"
run_case pm_domain 1 'pm_domain.nml:3: &point_mass' 'parameter domain'
printf "&run scenario = 'geometry', output = 'fold.h5' /\n&geometry kind = 'tube' /\n&centerline kind = 'helix', radius = 0.001, turns = 1 /\n" > "$work/fold.nml"
run_case fold 1 'fold.nml' 'fold'
printf "&run scenario = 'water', output = 'flat_channel.h5' /\n&channel kind = 'helix', pitch = 0.1 /\n" > "$work/flat_channel.nml"
run_case flat_channel 1 'flat_channel.nml:2:' 'the tube passes through itself'
sed -e 's/a = 0.025, b = 0.033/a = 0.025, b = 1.5/' -e "s|output = .*|output = 'egg_lifts.h5'|" \
  "$root/inputs/contact/egg.nml" > "$work/egg_lifts.nml"
run_case egg_lifts 1 'egg_lifts.nml:35: &contact' 'does not press'
sed -e "s|'../demo_slide/slide.nml'|'$root/inputs/demo_slide/slide.nml'|" -e "s|output = .*|output = 'heels.h5'|" \
  -e 's/u0 = 0.5, v0/u0 = 66.5, v0/' "$root/inputs/ride/demo_slide.nml" > "$work/heels.nml"
run_case heels 1 'heels.nml' '&rider' 'the heels cannot reach the slide'

# NaN, Inf and huge steps and durations in every scenario's shipped input,
# refused at the reader (in the Debug build no comparison ever sees a NaN)
for spec in point_mass/ellipsoid.nml:solver sled/bowl.nml:solver pendulum/double.nml:solver \
            fourbar/crank_rocker.nml:solver contact/egg.nml:solver water/demo_slide.nml:solver \
            ride/demo_slide.nml:solver ride/demo_slide.nml:water_solver; do
  input=${spec%%:*}; group=${spec##*:}
  for setting in output_step=NaN duration=NaN output_step=Inf duration=-Inf max_step=NaN rtol=1e308 \
                 max_steps=2147483648 output_step=1e-320; do
    checks=$((checks + 1))
    [ "$group$setting" = water_solverduration=NaN ] && continue   # the water's duration is the ride's
    out=$(cd "$root/inputs/$(dirname "$input")" && "$slidesim" -q --check --set "$group%$setting" \
          "$(basename "$input")" 2>&1); got=$?
    variable=${setting%%=*}
    [ $got = 1 ] && echo "$out" | grep -qF "&$group: $variable = ${setting#*=} is not allowed" || \
      fail "$input --set $group%$setting: exit $got: $out"
  done
done

finish
