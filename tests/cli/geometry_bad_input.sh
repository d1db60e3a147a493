#!/usr/bin/env bash
# Bad geometry input stops before any work: exit status 1, a message that names
# the file, the group, the variable (and where on the slide), no result file.
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

run="&run scenario = 'geometry', output = 'g.h5' /"
tube="&geometry kind = 'tube' /"
circle="&cross_section kind = 'circle', radius = 0.5 /"

printf "%s\n%s\n&centerline kind = 'points', n_points = 3, points = 0,0,0, 1,0,0, 2,0,0 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/too_few_points.nml"
expect too_few_points 1 too_few_points.nml '&centerline' n_points 'too few centerline points'

printf "%s\n%s\n&centerline kind = 'points', n_points = 5, points = 0,0,0, 1,0,0, 1,0,0, 2,0,0, 3,0,0 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/duplicate_points.nml"
expect duplicate_points 1 duplicate_points.nml '&centerline' 'points(:, 3)' 'duplicate consecutive'

printf "%s\n%s\n&centerline kind = 'line', start = 0,0,10, end = 0,0,0, horizon = 0,0,1 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/horizon_parallel.nml"
expect horizon_parallel 1 horizon_parallel.nml '&centerline' horizon 'parallel'

printf "%s\n%s\n&centerline kind = 'points', n_points = 5, points = 0,0,0, 1,0,-1, 2,0,-2, 3,0,-3, 4,0,-4, horizon = 1,0,-1 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/horizon_parallel_points.nml"
expect horizon_parallel_points 1 horizon_parallel_points.nml '&centerline' horizon 'parallel to the centerline between points 1 and 2'

printf "%s\n%s\n&centerline kind = 'helix', radius = 0.4, rise_per_turn = -1.0, turns = 1 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/folding.nml"
expect folding 1 folding.nml 'radius of curvature' 'arc length' 'fold onto itself'

cat > "$work/folding_slide.nml" <<NML
$run
&slide_elements n_elements = 2, kind = 'straight', 'curve', length = 3.0, 0.0,
  radius = 0.0, 0.45, angle_deg = 0.0, 90.0 /
&cross_section kind = 'circle', radius = 0.5 /
NML
expect folding_slide 1 folding_slide.nml '&slide_elements' 'radius of curvature' 'arc length' 'fold onto itself'

printf "%s\n%s\n&centerline kind = 'line' /\n&cross_section kind = 'profile', n_profile = 5, profile_y = 0, 1, 1, 0, 0.5, profile_z = 0, 0, 1, 1, -1 /\n" \
  "$run" "$tube" > "$work/self_intersecting_profile.nml"
expect self_intersecting_profile 1 self_intersecting_profile.nml '&cross_section' profile_y 'intersects itself'

printf "%s\n%s\n&centerline kind = 'line' /\n&cross_section kind = 'circle', radius = -0.5 /\n" \
  "$run" "$tube" > "$work/negative_radius.nml"
expect negative_radius 1 negative_radius.nml '&cross_section' 'radius(1)' '-0.5' '> 0'

cat > "$work/element_radius_zero.nml" <<NML
$run
&slide_elements n_elements = 2, kind = 'straight', 'curve', length = 3.0, 0.0, radius = 0.0, 0.0, angle_deg = 0.0, 90.0 /
NML
expect element_radius_zero 1 element_radius_zero.nml '&slide_elements' 'radius(2)' '> 0'

cat > "$work/unknown_element.nml" <<NML
$run
&slide_elements n_elements = 1, kind = 'loop' /
NML
expect unknown_element 1 unknown_element.nml '&slide_elements' 'kind(1)' "'loop'" straight

printf "&run scenario = 'point_mass', output = 'g.h5' /\n&surface kind = 'slide' /\n&point_mass /\n" > "$work/no_geometry_file.nml"
expect no_geometry_file 1 no_geometry_file.nml '&surface' geometry_file

echo "geometry_bad_input: $checks checks, $failures failed"
[ $failures = 0 ]
