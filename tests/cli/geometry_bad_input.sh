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
expect too_few_points 1 too_few_points.nml:3 '&centerline' 'n_points = 3' 'must be a whole number in [4, 2000]'

printf "%s\n%s\n&centerline kind = 'points', n_points = 2500 /\n%s\n" "$run" "$tube" "$circle" > "$work/too_many_points.nml"
expect too_many_points 1 too_many_points.nml:3 '&centerline' 'n_points = 2500' 'must be a whole number in [4, 2000]'

printf "%s\n%s\n&centerline kind = 'points', n_points = 6, points = 0,0,0, 1,0,0, 2,0,0, 3,0,0 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/points_missing.nml"
expect points_missing 1 points_missing.nml '&centerline' 'n_points = 6' 'only 4 points were given in points'

printf "%s\n%s\n&centerline kind = 'points', n_points = 4, points = 0,0,0, 1,0,0, 2,0,0, 3,0,0, 4,0,0 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/points_extra.nml"
expect points_extra 1 points_extra.nml '&centerline' 'n_points = 4' '5 points were given in points'

printf "%s\n%s\n&centerline kind = 'points', n_points = 4, points = 0,0,0, 1,0,0, 2,0,0, 3,0 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/points_partial.nml"
expect points_partial 1 points_partial.nml:3 '&centerline' 'points gives 11 numbers' 'not a multiple of 3'

printf "%s\n%s\n&centerline kind = 'points', n_points = 4, points = 0,0,0, 1,0,0, 2,0,0, 3,0,0, horizon_points = 0,0,1, 0,0,1 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/horizon_points_missing.nml"
expect horizon_points_missing 1 horizon_points_missing.nml '&centerline' 'horizon_points = 6 numbers' \
  'one horizon vector (3 numbers) per centerline point: 12 numbers for n_points = 4'

printf "%s\n%s\n&centerline kind = 'points', n_points = 5, points = 0,0,0, 1,0,0, 1,0,0, 2,0,0, 3,0,0 /\n%s\n" \
  "$run" "$tube" "$circle" > "$work/duplicate_points.nml"
expect duplicate_points 1 duplicate_points.nml '&centerline' 'points(:, 3)' 'duplicate consecutive'

# a point far off the others (inputs/geometry/points_tube.nml with a y of
# 2.5e3 for 5, cli_mutation's mutant 433): the quintic through them swings
# out to 1.5e8 m (3.3e8 m long), 15444 times the 2.5 km between points 4 and 5 there, and was
# accepted ("input ok"); the spline may be at most 3 times as long as the
# distance between two points. With 2.5e3 for 1 (point 3) it is 5.3 times
# (refused before only because the swing happened to pass through the tube)
sed "s/7.0, 5.0, -0.8/7.0, 2.5e3, -0.8/" inputs/geometry/points_tube.nml > "$work/point_far_off.nml"
expect point_far_off 1 point_far_off.nml:11 '&centerline: points: ' 'between points(:, 4) and points(:, 5)' \
  'it is 3.85629E+07 m long there' 'at most 3 times is allowed'
sed "s/4.0, 1.0, -0.4/4.0, 2.5e3, -0.4/" inputs/geometry/points_tube.nml > "$work/point_off.nml"
expect point_off 1 point_off.nml:11 '&centerline: points: ' 'between points(:, 2) and points(:, 3)' '5.2787' \
  'at most 3 times is allowed'

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
expect negative_radius 1 negative_radius.nml '&cross_section' 'radius(1) = -0.5' 'in [0.001, 100] (m)'

cat > "$work/element_radius_zero.nml" <<NML
$run
&slide_elements n_elements = 2, kind = 'straight', 'curve', length = 3.0, 0.0, radius = 0.0, 0.0, angle_deg = 0.0, 90.0 /
NML
expect element_radius_zero 1 element_radius_zero.nml '&slide_elements' 'radius(2)' '> 0'

cat > "$work/elements_missing.nml" <<NML
$run
&slide_elements n_elements = 3, kind = 'straight', 'curve', length = 3.0, 0.0, radius = 0.0, 6.0, angle_deg = 0.0, 90.0 /
NML
expect elements_missing 1 elements_missing.nml '&slide_elements' 'n_elements = 3' 'only 2 elements were given in kind'

cat > "$work/element_values_extra.nml" <<NML
$run
&slide_elements n_elements = 2, kind = 'straight', 'curve', length = 3.0, 0.0, 4.0, radius = 0.0, 6.0, angle_deg = 0.0, 90.0 /
NML
expect element_values_extra 1 element_values_extra.nml '&slide_elements' 'length = 3.0, 0.0, 4.0' '3 values are more than n_elements = 2'

printf "%s\n%s\n&centerline kind = 'line' /\n&cross_section n_sections = 2, kind = 'circle', radius = 0.5, 1.0 /\n" \
  "$run" "$tube" > "$work/sections_missing.nml"
expect sections_missing 1 sections_missing.nml '&cross_section' 'n_sections = 2' 'only 1 section was given in kind'

printf "%s\n%s\n&centerline kind = 'line' /\n&cross_section kind = 'circle', radius = 0.5, 0.6 /\n" \
  "$run" "$tube" > "$work/section_values_extra.nml"
expect section_values_extra 1 section_values_extra.nml '&cross_section' 'radius = 0.5, 0.6' '2 values are more than n_sections = 1'

printf "%s\n%s\n&centerline kind = 'line' /\n&cross_section n_sections = 2, kind = 'circle', 'circle', radius = 0.5, 1.0, transition_midpoint = 4, 6, transition_end = 5 /\n" \
  "$run" "$tube" > "$work/transitions_extra.nml"
expect transitions_extra 1 transitions_extra.nml '&cross_section' 'transition_midpoint = 4, 6' 'more than n_sections - 1 = 1 transitions'

printf "%s\n%s\n&centerline kind = 'line' /\n&cross_section kind = 'profile', n_profile = 6, profile_y = 0, 1, 1, 0, profile_z = 0, 0, 1, 1 /\n" \
  "$run" "$tube" > "$work/profile_missing.nml"
expect profile_missing 1 profile_missing.nml '&cross_section' 'n_profile = 6' 'only 4 points were given in profile_y'

printf "%s\n&geometry kind = 'blended' /\n&blended n_patches = 3, kind = 'elliptic_cylinder', 'elliptic_cylinder' /\n" \
  "$run" > "$work/patches_missing.nml"
expect patches_missing 1 patches_missing.nml '&blended' 'n_patches = 3' 'only 2 patches were given in kind'

printf "%s\n&geometry kind = 'blended' /\n&blended n_patches = 2, kind = 'elliptic_cylinder', 'elliptic_cylinder', u_max = 1, 2, 3 /\n" \
  "$run" > "$work/patch_values_extra.nml"
expect patch_values_extra 1 patch_values_extra.nml '&blended' 'u_max = 1, 2, 3' '3 values are more than n_patches = 2'

cat > "$work/unknown_element.nml" <<NML
$run
&slide_elements n_elements = 1, kind = 'loop' /
NML
expect unknown_element 1 unknown_element.nml '&slide_elements' 'kind(1)' "'loop'" straight

printf "&run scenario = 'point_mass', output = 'g.h5' /\n&surface kind = 'slide' /\n&point_mass /\n" > "$work/no_geometry_file.nml"
expect no_geometry_file 1 no_geometry_file.nml '&surface' geometry_file

echo "geometry_bad_input: $checks checks, $failures failed"
[ $failures = 0 ]
