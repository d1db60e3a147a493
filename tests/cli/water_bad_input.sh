#!/usr/bin/env bash
# The water scenario stops on bad input before any work: exit status 1, a
# message naming the file, &water, the variable, its value and what is
# allowed, and no result file. One check per input; a check with several
# failed conditions counts once, so the tally is checks = passed + failed.
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
  if ls "$work"/*.h5 "$work"/*.h5.tmp >/dev/null 2>&1; then
    echo "FAIL $name: a result file was left behind"; ok=0; rm -f "$work"/*.h5 "$work"/*.h5.tmp
  fi
  if [ $ok = 0 ]; then failures=$((failures + 1)); echo "  message: $(cat "$work/$name.err")"; fi
}

head="&run scenario = 'water', output = 'w.h5' /
&channel kind = 'straight', incline_deg = 10, length = 20 /"
mk() { printf "%s\n%s\n" "$head" "$2" > "$work/$1.nml"; }

mk negative_f1 "&water f1 = -0.01 /"
expect negative_f1 1 negative_f1.nml '&water' 'f1 = -0.01' 'in [0, 1000] (kg/m)'
mk negative_f3 "&water f3 = -1 /"
expect negative_f3 1 negative_f3.nml '&water' 'f3 = -1' 'in [0, 1000] (kg m)'
mk zero_q "&water flow_rate = 0 /"
expect zero_q 1 zero_q.nml '&water' 'flow_rate = 0' 'in [1.0E-06, 1] (m^3/s)'
mk negative_q "&water flow_rate = -0.004, start = 'height', height0 = 0.01 /"
expect negative_q 1 '&water' 'flow_rate = -0.004'
mk zero_speed "&water start = 'speed', speed0 = 0 /"
expect zero_speed 1 '&water' 'speed0 = 0' 'in [0.001, 100] (m/s)'
mk start_off_slide "&water u0 = 25 /"
expect start_off_slide 1 '&water' 'u0 = 25' 'on the slide'
mk height_over_tube "&water start = 'height', height0 = 1.2 /"
expect height_over_tube 1 '&water' 'start height' 'inside the section'
mk edges_swapped "&water v_left0 = 1.2, v_right0 = 1.9 /"
expect edges_swapped 1 '&water' 'v_left0, v_right0' 'larger v'
mk bad_correction "&water correction = 'partial' /"
expect bad_correction 1 '&water' "'partial'" 'full no_radius off'
mk unknown_variable "&water flowrate = 0.004 /"
expect unknown_variable 1 '&water' 'flowrate' 'allowed:'
mk station_off_slide "&water stations = 5.0, 30.0 /"
expect station_off_slide 1 '&water' 'stations = 30' 'on the slide'
mk stations_decreasing "&water stations = 5.0, 3.0 /"
expect stations_decreasing 1 '&water' 'stations(2)' 'increase'
# NaN and Inf (gfortran reads both in a namelist): every message names the
# input file, the group, the variable and the value as given
for case in "flow_rate NaN" "flow_rate Inf" "f1 NaN" "f1 -Inf" "speed0 NaN" "speed0 Infinity"; do
  set -- $case
  var=$1; value=$2; shown=$value
  [ "$value" = Infinity ] && shown=Inf
  name="${var}_${value#-}"
  extra=""
  [ "$var" = speed0 ] && extra="start = 'speed', "
  mk "$name" "&water $extra$var = $value /"
  expect "$name" 1 "$name.nml" '&water' "$var = $shown" 'finite'
done
for value in NaN Inf; do
  name="rtol_$value"
  printf "&run scenario = 'water', output = 'w.h5' /\n&solver rtol = %s /\n&channel kind = 'straight' /\n&water /\n" \
    "$value" > "$work/$name.nml"
  expect "$name" 1 "$name.nml" '&solver' "rtol = $value"
done

# a start outside an open flume's section (v in [-wall/r, pi + wall/r] =
# [-0.3154, 3.4570] rad): the water middle v0, or the start edges
cat > "$work/flume_geometry.nml" <<'NML'
&geometry kind = 'slide' /
&slide_elements n_elements = 1, kind = 'straight', length = 20.0, slope_deg = 8.0 /
&cross_section kind = 'flume', radius = 0.52, wall = 0.164 /
NML
flume="&run scenario = 'water', output = 'w.h5' /
&surface kind = 'slide', geometry_file = 'flume_geometry.nml' /"
printf "%s\n%s\n" "$flume" "&water start = 'speed', speed0 = 1.5, v0 = 4.0 /" > "$work/flume_v0_above.nml"
expect flume_v0_above 1 flume_v0_above.nml '&water' 'v0 = 4.0' 'inside the cross-section' '3.45697'
printf "%s\n%s\n" "$flume" "&water start = 'height', height0 = 0.02, v0 = -0.5 /" > "$work/flume_v0_below.nml"
expect flume_v0_below 1 flume_v0_below.nml '&water' 'v0 = -0.5' 'inside the cross-section' '-0.31538'
printf "%s\n%s\n" "$flume" "&water v_left0 = 3.6, v_right0 = 3.0 /" > "$work/flume_edges_outside.nml"
expect flume_edges_outside 1 flume_edges_outside.nml '&water' 'v_left0, v_right0 = 3.6, 3.0' 'inside the cross-section'

printf "&run scenario = 'water', output = 'w.h5' /\n&channel kind = 'helix', radius = 0.5, helix_radius = 0.4 /\n&water /\n" > "$work/folding_helix.nml"
expect folding_helix 1 '&channel' 'helix_radius = 0.4' 'folds'
# the geometry layer refuses these (build_channel); the line named is the variable's
printf "&run scenario = 'water', output = 'w.h5' /\n&channel kind = 'helix',\n  turn_sense = 0.5 /\n&water /\n" > "$work/half_turn_sense.nml"
expect half_turn_sense 1 'half_turn_sense.nml:3: &channel: turn_sense = 0.5 is not allowed: must be +1 or -1'
printf "&run scenario = 'water', output = 'w.h5' /\n&channel kind = 's_bend',\n wavenumber = 3.0 /\n" > "$work/folding_s_bend.nml"
expect folding_s_bend 1 'folding_s_bend.nml:2: &channel: tube surface: radius of curvature' 'fold'
printf "&run scenario = 'water', output = 'w.h5' /\n&surface kind = 'ellipsoid' /\n&water /\n" > "$work/not_a_tube.nml"
expect not_a_tube 1 '&surface' 'needs a tube'

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
