#!/usr/bin/env bash
# A long slide rides like a short one (issue 27, point 8): real slides run
# 100-250 m, and a ride without &solver duration on one longer than about
# 130 m was refused as "over 2 GB of outputs" (the outputs sized by the safety
# bound 10 x length / min_speed = 50000 s here, 4.8 GB at output_step 0.01 s).
# A 250 m slide of standard elements (straights at 6 degrees, a 90 degree
# curve, a run-out) is checked and ridden to its end: exit 0, a complete file,
# the ride's records grown as it went (about 35 s of ride, 3500 outputs).
set -u
slidesim=$1
. "$(dirname "$0")/support/cli_checks.sh"

cat > "$work/long.nml" <<'NML'
&run scenario = 'ride', output = 'long.h5' /
&surface kind = 'slide' /
&slide_elements
  n_elements = 4, start = 0.0, 0.0, 30.0
  kind      = 'straight', 'curve', 'straight', 'runout'
  length    = 105.0,      0.0,     105.0,      20.0
  slope_deg = 6.0,        5.0,     6.0,        1.0
  radius    = 0.0,        15.0,    0.0,        0.0
  angle_deg = 0.0,        90.0,    0.0,        0.0
  direction = 'left',     'left',  'left',     'left'
/
&cross_section radius = 0.5 /
&water flow_rate = 0.004 /
&rider mu = 0.0724419, u0 = 0.5, speed0 = 1.0 /
&solver max_step = 0.05 /
NML
run_case long 0
length=$(sed -n 's/^  slide centreline length *\([0-9.]*\) m$/\1/p' "$work/long.out")
awk -v l="${length:-0}" 'BEGIN { exit !(l >= 250 && l < 260) }' || fail "long: the slide is '$length' m, not 250 m"
grep -q "ride ended *end of the slide" "$work/long.out" || \
  fail "long: the ride did not reach the end: $(grep 'ride ended' "$work/long.out")"
# a duration the input gives is still bounded before the run
cp "$work/long.nml" "$work/bounded.nml"
sed -i -e "s/output = 'long.h5'/output = 'bounded.h5'/" -e 's/^&solver .*/\&solver max_step = 0.05, duration = 1e6 \//' \
  "$work/bounded.nml"
run_case bounded 1 'bounded.nml' 'output_step = 0.01' 'raise output_step or shorten duration'

finish
