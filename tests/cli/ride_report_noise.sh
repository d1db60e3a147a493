#!/usr/bin/env bash
# Rounding noise is no finding (design_ride_evaluation's noise_free: below
# 1e-9 of the quantity's scale, printed as 0 with no direction), on the
# shipped jump (inputs/ride/jump.nml: a straight slide, no sideways force):
# - the felt lateral max and min print "0 g" and name no side (on 3e73489
#   "3.07E-16 g, pushed to the left"), the largest tipping lever arm "0 m"
#   (was -4.04E-17 m), the pelvis's normal force min "0 N" (was -7.19E-10 N:
#   the flying pelvis presses nothing); no figure of the report is printed
#   in E-notation below 1e-9; --summary-json has the same zeros;
# - the limit lines give felt accelerations in g, as their bounds (was
#   "worst 0 gravity"), and angles in deg;
# - a limit's verdict judges the values as printed (noise is 0): the
#   normal force >= 0 N and lever arm <= 0 m limits hold;
# - a felt acceleration above the floor keeps its sign and direction:
#   the demo ride's lateral max "0.0.. g, pushed to the left" (report_words).
slidesim=$1
. "$(dirname "$0")/support/checks.sh"

ride_with_limits inputs/ride/jump.nml \
  "'airtime','drop_height','acceleration_lateral','acceleration_normal','wall_angle','normal_force','lever_arm'" \
  "'s','m','g','g','deg','N','m'" "0,0,-1,0.2,0,0,-1" "0.6,0.2,1,10,60,5000,0"
check '[ $(grep -c "^  felt lateral m[ai][xn]  *0 g$" "$work/jump.out") = 2 ]' \
  "lateral: $(grep 'felt lateral' "$work/jump.out")"
check '! grep -q "pushed to the" "$work/jump.out"' "a side named: $(grep 'pushed to the' "$work/jump.out")"
check 'grep -q "^  largest tipping lever arm  *0 m$" "$work/jump.out"' "lever arm: $(grep 'lever arm' "$work/jump.out")"
check 'grep -q "^  pelvis normal force min  *0 N$" "$work/jump.out"' \
  "pelvis normal force: $(grep 'pelvis normal force' "$work/jump.out")"
check '! grep -E -q "[0-9]E-(09|[1-9][0-9])" "$work/jump.out"' "noise printed: $(grep -E '[0-9]E-(09|[1-9][0-9])' "$work/jump.out")"
check 'grep -q "LIMIT EXCEEDED: acceleration_normal >= 0.2 g and <= 10 g; worst 0 g at arc length" "$work/jump.out"' \
  "normal limit: $(grep acceleration_normal "$work/jump.out")"
check 'grep -q "limit acceleration_lateral >= -1 g and <= 1 g: ok (closest 0 g at" "$work/jump.out"' \
  "lateral limit: $(grep acceleration_lateral "$work/jump.out")"
check 'grep -q "limit wall_angle >= 0 deg and <= 60 deg: ok (closest [0-9.]* deg at" "$work/jump.out"' \
  "wall angle limit: $(grep 'limit wall_angle' "$work/jump.out")"
# a verdict judges what the report prints: the flying pelvis's -7e-10 N and
# the lever arm's 4e-17 m are no excess (on 07f4aea both "LIMIT EXCEEDED ...
# worst 0 N" / "worst 0 m")
check 'grep -q "limit normal_force >= 0 N and <= 5000 N: ok (closest 0 N at" "$work/jump.out"' \
  "normal force limit: $(grep 'normal_force' "$work/jump.out")"
check 'grep -q "limit lever_arm >= -1 m and <= 0 m: ok (closest 0 m at" "$work/jump.out"' \
  "lever arm limit: $(grep 'limit lever_arm\|LIMIT.*lever_arm' "$work/jump.out")"
check '! grep -q "gravity\|degree" "$work/jump.out"' "units spelt for files: $(grep 'gravity\|degree' "$work/jump.out")"
"$py" - "$work/jump.json" >"$work/check.out" 2>&1 <<'EOF'
import sys, json
j = json.load(open(sys.argv[1]))['values']
bad = [k for k in ('felt_lateral_max', 'felt_lateral_min', 'lever_arm_max', 'pelvis_normal_force_min')
       if j[k] != 0]
assert not bad, [(k, j[k]) for k in bad]
print('ok')
EOF
rc=$?
check '[ $rc = 0 ]' "the JSON: $(cat "$work/check.out")"

echo "ride_report_noise: $checks checks, $failures failed"
[ $failures = 0 ]
