#!/usr/bin/env bash
# Runaway runs (issue 12, item 5): a body at rest under Coulomb friction with
# Adams (the sled: millions of microsecond steps before the guard) stops
# within a bounded time as a failed run (exit 2, the file kept and marked
# incomplete) with a message that suggests BDF, and BDF runs it; every
# scenario prints progress lines while it runs (--progress SECONDS sets their
# interval; here the smallest, a line at every output time).
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

# the sled at rest on a 20-degree incline with mu = 0.5 (it sticks)
sed -e "s|output = .*|output = 'rest_adams.h5'|" -e 's/mu = 0.2/mu = 0.5/' -e 's/du0 = 1.0/du0 = 0.0/' \
  "$root/inputs/sled/incline_coulomb.nml" > "$work/rest_adams.nml"
start=$(date +%s)
run_case rest_adams 2 'sled: runaway integration' "use method = 'bdf' in &solver"
[ $(( $(date +%s) - start )) -lt 30 ] || fail "rest_adams: the guard took $(( $(date +%s) - start )) s"
sed -e "s|output = .*|output = 'rest_bdf.h5'|" -e "s|rtol = 1e-10|method = 'bdf', rtol = 1e-10|" \
  "$work/rest_adams.nml" > "$work/rest_bdf.nml"
run_case rest_bdf 0
grep -q 'stopped at *the end of the simulated time' "$work/rest_bdf.out" || fail "rest_bdf: $(cat "$work/rest_bdf.out")"

# The guard follows the tolerances (issue 27): the egg with Coulomb friction
# at P1 (rtol 1e-11) is sound, and BDF integrates it with mean steps of
# 3.4e-5 s (main's fixed 1e-4 s guard stopped it at 1.23 s, exit 2); under
# Adams it is stiff (rolling with a regularized Coulomb law): the guard stops
# it (at 0.77 s) and says to use BDF, the guard's limit and how to change it.
coulomb=(--set "contact%friction='coulomb'" --set solver%duration=2)
sed -e "s|output = .*|output = 'egg_bdf.h5'|" -e "s|method = 'adams'|method = 'bdf'|" \
  "$root/inputs/contact/egg.nml" > "$work/egg_bdf.nml"
extra_args="${coulomb[*]}" run_case egg_bdf 0
grep -q 'stopped at *the end of the simulated time' "$work/egg_bdf.out" || fail "egg_bdf: $(cat "$work/egg_bdf.out")"
sed -e "s|output = .*|output = 'egg_adams.h5'|" "$root/inputs/contact/egg.nml" > "$work/egg_adams.nml"
extra_args="${coulomb[*]}" run_case egg_adams 2 'contact: runaway integration' 'below the guard 1.4678' \
  "use method = 'bdf' in &solver" 'set max_step in &solver, the guard becomes a tenth of it'

# progress lines in every scenario (the water's and the ride's as the share
# of the slide covered, the optimisation as designs evaluated, the others as
# the share of the time)
progress() {   # INPUT PATTERN [--set ...]
  local input=$1 pattern=$2; shift 2
  checks=$((checks + 1))
  local name
  name=$(basename "$(dirname "$input")")_$(basename "$input" .nml)
  (cd "$root/inputs/$(dirname "$input")" && "$slidesim" --progress 1e-6 -o "$work/$name.h5" "$@" \
    "$(basename "$input")" > "$work/$name.out" 2> "$work/$name.err") || \
    fail "progress $input: exit $?: $(tail -3 "$work/$name.err")"
  grep -qE "$pattern" "$work/$name.err" || fail "progress $input: no line like '$pattern': $(head -5 "$work/$name.err")"
}
short=(--set solver%duration=0.05)
progress point_mass/ellipsoid.nml '^point_mass: [0-9.]+ % \(t = ' "${short[@]}"
progress sled/bowl.nml '^sled: [0-9.]+ % \(t = ' "${short[@]}"
progress pendulum/double.nml '^pendulum: [0-9.]+ % \(t = ' "${short[@]}"
progress fourbar/crank_rocker.nml '^fourbar: [0-9.]+ % \(t = ' "${short[@]}"
progress contact/egg.nml '^contact: [0-9.]+ % \(t = ' "${short[@]}"
progress water/demo_slide.nml '^water: [0-9.]+ % \(t = .* s, u = ' "${short[@]}"
progress ride/demo_slide.nml '^ride: [0-9.]+ % \(t = .* m down the slide\)' "${short[@]}"
grep -qE '^water: [0-9.]+ %' "$work/ride_demo_slide.err" || fail "progress ride: no line of its water stage"
progress design/optimize_table_4_12.nml '^optimize: [0-9]+ designs evaluated \([0-9]+ rides\)'
progress geometry/helix_tube.nml '^surface grid: [0-9]+ % \([0-9]+ of 400 u values\)'
# without --progress: none on a short run; -q: none at all
checks=$((checks + 1))
(cd "$root/inputs/point_mass" && "$slidesim" -o "$work/p.h5" "${short[@]}" ellipsoid.nml 2>&1 >/dev/null | grep -q '%') && \
  fail "progress lines on a short run without --progress"
checks=$((checks + 1))
(cd "$root/inputs/point_mass" && "$slidesim" -q --progress 1e-6 -o "$work/p.h5" "${short[@]}" ellipsoid.nml 2>&1 \
  >/dev/null | grep -q .) && fail "-q --progress: lines on standard error"

# --progress takes seconds, a number > 0
for value in 0 -1 NaN Inf 1e400 abc ''; do
  checks=$((checks + 1))
  out=$("$slidesim" --progress="$value" --check "$root/inputs/point_mass/ellipsoid.nml" 2>&1); got=$?
  [ $got = 1 ] && echo "$out" | grep -qF -- "--progress $value: give the seconds between progress lines" || \
    fail "--progress=$value: exit $got: $out"
done

finish
