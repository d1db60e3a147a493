#!/usr/bin/env bash
# The input examples of issue 12: damaged, truncated, non-finite, huge and
# unused values are refused with a message that names the file, the line, the
# group, the variable, the value and what is allowed (exit 1, no file); values
# that pass can no longer overflow or write NaN (both builds run this).
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

plane="&surface kind = 'plane', point_a = 0.0, 0.0, 0.0, point_b = 0.866, 0.0, -0.5, point_c = 0.0, 1.0, 0.0 /"
mass="&point_mass du0 = 1.0 /"
solver="&solver duration = 1.0, output_step = 0.1 /"
pm() { printf "&run output = '%s.h5' /\n%s\n" "$1" "$2" > "$work/$1.nml"; }

# a file cut inside a group: the plane must not silently turn horizontal
printf "&run output = 'cut.h5' /\n%s\n%s\n&surface kind = 'plane', point_b = 0.866, 0.0, -" "$solver" "$mass" > "$work/cut.nml"
run_case cut 1 'cut.nml:4:' '&surface' 'not closed' 'cut short'
# ... or cut between two values of a group
printf "&run output = 'cut2.h5' /\n&surface kind = 'plane'\n  point_b = 0.866, 0.0,\n" > "$work/cut2.nml"
run_case cut2 1 'cut2.nml:3:' '&surface (opened at line 2) is not closed'

# a line longer than 512 characters is read whole (the value at its end counts)
pm long "$(printf '%s\n%s\n&point_mass mass = 2.0, %*s du0 = 1.0 /' "$solver" "$plane" 600 '')"
run_case long 0
grep -q 'results' "$work/long.out" || fail "long: no summary"

# a text longer than its variable
printf "&run output = 'kind_long.h5' /\n&surface kind = 'plane%s' /\n" "$(printf 'x%.0s' $(seq 292))" > "$work/kind_long.nml"
run_case kind_long 1 'kind_long.nml:2:' '&surface' "kind = 'planexxx" 'must be one of'
printf "&run output = 'title_long.h5', title = '%s' /\n" "$(printf 'y%.0s' $(seq 300))" > "$work/title_long.nml"
run_case title_long 1 'title_long.nml:1:' '&run' 'title' 'longer than the 256 characters allowed'

# non-finite and huge values, wherever they stand
pm inf_station "$(printf "&surface kind = 'slide' /\n")"
printf "&run scenario = 'water', output = 'inf_station.h5' /\n&water stations = 5, 10, -Inf /\n" > "$work/inf_station.nml"
run_case inf_station 1 'inf_station.nml:2:' '&water' 'stations(3) = -Inf' 'must be a finite number in [0, 1000000] (m)'
printf "&run scenario = 'geometry', output = 'midpoint.h5' /\n&geometry kind = 'blended' /\n&blended n_patches = 3, kind = 3*'elliptic_paraboloid'\n  transition = 1.0, 1.0, midpoint = 2.5, -Inf, u_99 = 3.0, 6.0 /\n" > "$work/midpoint.nml"
run_case midpoint 1 'midpoint.nml:4:' '&blended' 'midpoint(2) = -Inf' 'must be a finite number'
printf "&run scenario = 'geometry', output = 'v_min.h5' /\n&geometry kind = 'blended' /\n&blended n_patches = 2, kind = 2*'elliptic_paraboloid'\n  v_min = NaN, -1.0 /\n" > "$work/v_min.nml"
run_case v_min 1 'v_min.nml:4:' '&blended' 'v_min(1) = NaN'
pm u0_huge "$(printf '%s\n%s\n&point_mass u0 = 1e308 /' "$solver" "$plane")"
run_case u0_huge 1 'u0_huge.nml:4:' '&point_mass' 'u0 = 1e308' 'must be a finite number in [-1000000, 1000000]'
pm gravity_huge "$(printf '%s\n%s\n&point_mass gravity = 0, 0, 1e308 /' "$solver" "$plane")"
run_case gravity_huge 1 'gravity_huge.nml:4:' 'gravity(3) = 1e308' 'in [-1000, 1000] (m/s^2)'
pm angles_huge "$(printf '%s\n&surface kind = '"'"'ellipsoid'"'"', angles_deg = 0, 1e308, 0 /\n%s' "$solver" "$mass")"
run_case angles_huge 1 'angles_huge.nml:3:' 'angles_deg(2) = 1e308' 'in [-360, 360] (deg)'
printf "&run scenario = 'geometry', output = 'angles_patch.h5' /\n&geometry kind = 'blended' /\n&blended n_patches = 2, kind = 2*'elliptic_paraboloid'\n  angles_deg(:, 2) = 0.0, 1e308, 0.0 /\n" > "$work/angles_patch.nml"
run_case angles_patch 1 'angles_patch.nml:4:' 'angles_deg(2, 2) = 1e308'
pm max_steps "$(printf '&solver max_steps = 1e308 /\n%s\n%s' "$plane" "$mass")"
run_case max_steps 1 'max_steps.nml:2:' '&solver' 'max_steps = 1e308' 'must be a whole number in [1, 100000000]'
pm int_overflow "$(printf '&solver max_steps = 2147483648 /\n%s\n%s' "$plane" "$mass")"
run_case int_overflow 1 'int_overflow.nml:2:' 'max_steps = 2147483648' 'whole number'
pm two_values "$(printf '&solver rtol = 1e-8, 0.02 /\n%s\n%s' "$plane" "$mass")"
run_case two_values 1 'two_values.nml:2:' '&solver' 'rtol = 1e-8, 0.02' 'a single value is expected'
pm logical_mass "$(printf '%s\n%s\n&point_mass mass = .true. /' "$solver" "$plane")"
run_case logical_mass 1 'logical_mass.nml:4:' '&point_mass' 'mass = .true.' 'must be a finite number'
pm e308 "$(printf '&solver max_steps = 1 e308 /\n%s\n%s' "$plane" "$mass")"
run_case e308 1 'e308.nml:2:' '&solver' 'max_steps = 1, e308' 'a single value is expected'

# tiny steps and the sizes derived from them, bounded before any work
pm output_tiny "$(printf '&solver output_step = 1e-320 /\n%s\n%s' "$plane" "$mass")"
run_case output_tiny 1 'output_tiny.nml:2:' 'output_step = 1e-320' 'in [1.0E-09, 1000000] (s)'
pm outputs_many "$(printf '&solver duration = 1e9, output_step = 0.1 /\n%s\n%s' "$plane" "$mass")"
run_case outputs_many 1 'outputs_many.nml:2:' '&solver' 'output_step = 0.1' 'duration = 1.0E+09 s' 'raise output_step'
printf "&run scenario = 'water', output = 'table_tiny.h5' /\n&water table_step = 1e-9 /\n" > "$work/table_tiny.nml"
run_case table_tiny 1 'table_tiny.nml:2:' '&water' 'table_step = 1e-9' 'in [1.0E-04, 1000] (m)'
printf "&run scenario = 'water', output = 'table_rows.h5' /\n&channel length = 1000 /\n&water table_step = 1e-4 /\n" > "$work/table_rows.nml"
run_case table_rows 1 'table_rows.nml:3:' 'table_step' 'raise table_step'
printf "&run scenario = 'geometry', output = 'grid_huge.h5' /\n&geometry kind = 'tube' /\n&centerline kind = 'line' /\n&grid n_u = 100000, n_v = 10000 /\n" > "$work/grid_huge.nml"
run_case grid_huge 1 'grid_huge.nml:4:' '&grid' 'n_u, n_v = 100000, 10000' 'more than'

# water runs to the end of the slide unless &solver duration bounds it
sed -e '/^&solver/,/^\//d' -e "s|'../demo_slide/slide.nml'|'$root/inputs/demo_slide/slide.nml'|" \
    -e "s|output = .*|output = 'water_to_end.h5'|" "$root/inputs/water/demo_slide.nml" > "$work/water_to_end.nml"
run_case water_to_end 0
grep -q 'stopped at *end of slide' "$work/water_to_end.out" || fail "water_to_end: did not run to the end: $(grep stopped "$work/water_to_end.out")"
! grep -q 'not reached' "$work/water_to_end.out" || fail "water_to_end: stations not reached"
# ... and a run bounded by duration says that the end was not reached
sed -e "s|duration = 60.0|duration = 5.0|" -e "s|'../demo_slide/slide.nml'|'$root/inputs/demo_slide/slide.nml'|" \
    -e "s|output = .*|output = 'water_bounded.h5'|" "$root/inputs/water/demo_slide.nml" > "$work/water_bounded.nml"
run_case water_bounded 0
h5dump -a /status_message "$work/water_bounded.h5" | grep -q 'its end not reached' || \
  fail "water_bounded: the status message does not say the slide's end was not reached"

# builds that fail on the input are bad input (exit 1, no file), not a failed run
printf "&run scenario = 'sled', output = 'sled_v0.h5' /\n&surface kind = 'plane' /\n&sled v0 = 1e308 /\n" > "$work/sled_v0.nml"
run_case sled_v0 1 'sled_v0.nml:3:' '&sled' 'v0 = 1e308'
printf "&run scenario = 'geometry', output = 'thin_helix.h5' /\n&geometry kind = 'tube' /\n&centerline kind = 'helix', radius = 0.001, turns = 1 /\n" > "$work/thin_helix.nml"
run_case thin_helix 1 'thin_helix.nml' '&centerline with &cross_section' 'fold'

# a parameter the element does not use, and a tube that passes through itself
printf "&run scenario = 'geometry', output = 'helix_slope.h5' /\n&slide_elements n_elements = 1, kind = 'helix', radius = 2.0, turns = 2.0,\n  slope_deg = 10.0 /\n&cross_section radius = 0.5 /\n" > "$work/helix_slope.nml"
run_case helix_slope 1 'helix_slope.nml:3:' '&slide_elements' 'slope_deg(1) = 10.0' 'a helix does not use slope_deg'
printf "&run scenario = 'geometry', output = 'flat_helix.h5' /\n&slide_elements n_elements = 1, kind = 'helix', radius = 2.0, turns = 2.0 /\n&cross_section radius = 1.1 /\n" > "$work/flat_helix.nml"
run_case flat_helix 1 'flat_helix.nml' 'the tube passes through itself' 'arc length 0 m' 'less than the cross-section extents 1.1 + 1.1 m'
printf "&run scenario = 'water', output = 'flat_channel.h5' /\n&channel kind = 'helix', pitch = 0.1 /\n" > "$work/flat_channel.nml"
run_case flat_channel 1 'flat_channel.nml:2:' '&channel' 'the tube passes through itself'
printf "&run scenario = 'water', output = 'unused_channel.h5' /\n&channel kind = 'helix', incline_deg = 20 /\n" > "$work/unused_channel.nml"
run_case unused_channel 1 'unused_channel.nml:2:' 'incline_deg = 20' 'a helix channel does not use it'
pm unused_axes "$(printf '%s\n&surface kind = '"'"'plane'"'"', c = 2.0 /\n%s' "$solver" "$mass")"
run_case unused_axes 1 'unused_axes.nml:3:' '&surface' 'c = 2.0' "kind = 'plane' does not use it"

# a CSV value too large for the surface
mkdir -p "$work/csv"
{ echo "x, y, z"; for x in -1 0 1 2; do for y in -1 0 1 2; do
  if [ "$x$y" = 11 ]; then echo "$x, $y, 1e308"; else echo "$x, $y, 0.1"; fi; done; done; } > "$work/csv/grid.csv"
printf "&run scenario = 'geometry', output = 'csv_huge.h5' /\n&geometry kind = 'bspline' /\n&bspline file = 'csv/grid.csv', layout = 'grid' /\n" > "$work/csv_huge.nml"
run_case csv_huge 1 'csv_huge.nml:3:' '&bspline' 'csv/grid.csv:12: column 3' "'1e308' is not allowed" 'in [-1000000, 1000000] (m)'

# files that are not inputs
cp "$slidesim" "$work/binary.nml"
run_case binary 1 'binary.nml:1:' 'is not text'
cp "$root/inputs/geometry/bump_grid.csv" "$work/a_csv.nml"
run_case a_csv 1 'a_csv.nml:1:' 'text outside a group' '# a smooth bump'
printf "&run scenario = 'geometry' /\n&surface kind = 'slide', geometry_file = 'the_input.nml' /\n" > "$work/the_input.nml"
printf "&run scenario = 'point_mass', output = 'geometry_self.h5' /\n&surface kind = 'slide', geometry_file = 'the_input.nml' /\n" > "$work/geometry_self.nml"
run_case geometry_self 1 'geometry_self.nml:2:' "geometry_file = 'the_input.nml'" 'unknown namelist group &surface'
# files that are not inputs
: > "$work/empty.nml"
run_case empty 1 'empty.nml' 'is empty'
mkdir "$work/folder.nml"
run_case folder 3 'folder.nml' 'is a folder'
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q -o devnull.h5 /dev/null > devnull.out 2> devnull.err); got=$?
[ $got = 1 ] || fail "/dev/null as the input: exit $got"
grep -q '/dev/null: the input is empty' "$work/devnull.err" || fail "/dev/null as the input: $(cat "$work/devnull.err")"
check_files devnull 1

# ... and geometry files that are not geometry inputs: each named with the
# line of geometry_file in the input, never read as a geometry of defaults
geometry_file_case() {   # NAME WANT GEOMETRY_FILE NEEDLE...
  local name=$1 want=$2 file=$3; shift 3
  printf "&run output = '%s.h5' /\n&surface kind = 'slide', geometry_file = '%s' /\n%s\n" "$name" "$file" "$mass" \
    > "$work/$name.nml"
  run_case "$name" "$want" "$name.nml:2: &surface: geometry_file = '$file'" "$@"
}
geometry_file_case gf_proc 1 /proc/self/status '/proc/self/status:1: text outside a group'
geometry_file_case gf_csv 1 csv/grid.csv 'csv/grid.csv:1: text outside a group'
geometry_file_case gf_binary 1 binary.nml 'binary.nml:1: byte 0x7F is not text'
geometry_file_case gf_devnull 1 /dev/null '/dev/null is empty: it has no namelist groups' '&slide_elements'
: > "$work/empty_geometry.nml"
geometry_file_case gf_empty 1 empty_geometry.nml 'empty_geometry.nml is empty'
geometry_file_case gf_folder 3 folder.nml 'is a folder'
geometry_file_case gf_missing 3 no_such.nml 'does not exist'
geometry_file_case gf_other 1 "$root/inputs/point_mass/ellipsoid.nml" 'ellipsoid.nml:7: unknown namelist group &solver'
geometry_file_case gf_tube 1 "$root/inputs/geometry/helix_tube.nml" \
  'helix_tube.nml has no &slide_elements, which a slide surface needs'
# an error inside the geometry file names both places
sed -e 's/radius = 0.52/radius = -0.52/' "$root/inputs/design/second_slide.nml" > "$work/bad_slide.nml"
geometry_file_case gf_bad_value 1 bad_slide.nml 'bad_slide.nml:' '&cross_section' 'radius(1) = -0.52 is not allowed'

# a blend whose transition has no length (the blend would have no width)
printf "&run scenario = 'geometry', output = 'blend_zero.h5' /\n&geometry kind = 'blended' /\n&blended n_patches = 2, kind = 2*'elliptic_cylinder'\n  transition = 0.0 /\n" > "$work/blend_zero.nml"
run_case blend_zero 1 'blend_zero.nml:4:' '&blended' 'transition(1) = 0' 'needs an explicit midpoint and u_99'
printf "&run scenario = 'geometry', output = 'blend_u99.h5' /\n&geometry kind = 'blended' /\n&blended n_patches = 2, kind = 2*'elliptic_cylinder'\n  transition = 1.0, midpoint = 2.0, u_99 = 1.5 /\n" > "$work/blend_u99.nml"
run_case blend_u99 1 'blend_u99.nml:4:' '&blended' 'u_99(1) = 1.5' 'must lie after midpoint(1) = 2.0'

# contact models that cannot start name the &contact or &body they are about
sed -e 's/a = 0.025, b = 0.033/a = 0.025, b = 1.5/' -e "s|output = .*|output = 'egg_lifts.h5'|" \
  "$root/inputs/contact/egg.nml" > "$work/egg_lifts.nml"
run_case egg_lifts 1 'egg_lifts.nml:35: &contact name = '"'egg_on_table'" 'does not press'
sed -e 's/angular_velocity = 0.0, 0.0, 150.0/angular_velocity = 0.0, 0.0, 150.0, velocity = 0, 0, -1/' \
  -e "s|output = .*|output = 'egg_sinks.h5'|" "$root/inputs/contact/egg.nml" > "$work/egg_sinks.nml"
run_case egg_sinks 1 'egg_sinks.nml:26: &body name = '"'egg'" 'start velocities are not consistent'
printf "&run scenario = 'contact', output = 'no_contact.h5' /\n&shape name = 'table', kind = 'plane' /\n" > "$work/no_contact.nml"
run_case no_contact 1 'no_contact.nml: &contact is missing: a contact scenario needs at least one &contact'

finish
