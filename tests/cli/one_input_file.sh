#!/usr/bin/env bash
# One input file per run (issue 13, item 5): the geometry groups stand in the
# run's own input (point_mass, water, sled, ride on the demo slide), and
# centerline points may come from a CSV file, checked cell by cell. The
# results equal those of the two-file form.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

# the demo slide's point mass, once with geometry_file, once in one file
sed -e "s|'slide.nml'|'$root/inputs/demo_slide/slide.nml'|" -e "s|output = .*|output = 'two_files.h5'|" \
    -e 's|duration = 8.0|duration = 2.0|' "$root/inputs/demo_slide/point_mass.nml" > "$work/two_files.nml"
run_case two_files 0
{ sed -e '/geometry_file/d' -e "s|output = .*|output = 'one_file.h5'|" -e 's|duration = 8.0|duration = 2.0|' \
    "$root/inputs/demo_slide/point_mass.nml"
  sed -e '/^&run/,/^\//d' -e '/^&grid/,/^\//d' "$root/inputs/demo_slide/slide.nml"; } > "$work/one_file.nml"
run_case one_file 0
if [ -f "$work/one_file.h5" ] && [ -f "$work/two_files.h5" ]; then
  h5diff "$work/one_file.h5" "$work/two_files.h5" /point_mass/position /point_mass/position >/dev/null || \
    fail "one_file: positions differ from the two-file run"
fi

# the other scenarios that run on a slide: the geometry groups in the input
# give the same results as geometry_file (short runs)
for spec in water:/water/speed sled:/sled/bodies/bar_mass/position ride:/rider/speed; do
  scenario=${spec%%:*}; dataset=${spec#*:}
  sed -e "s|'../demo_slide/slide.nml'|'$root/inputs/demo_slide/slide.nml'|" \
      -e "s|output = .*|output = '${scenario}_two.h5'|" "$root/inputs/$scenario/demo_slide.nml" > "$work/${scenario}_two.nml"
  { sed -e '/geometry_file/d' -e "s|output = .*|output = '${scenario}_one.h5'|" "$root/inputs/$scenario/demo_slide.nml"
    sed -e '/^&run/,/^\//d' -e '/^&grid/,/^\//d' "$root/inputs/demo_slide/slide.nml"; } > "$work/${scenario}_one.nml"
  extra_args="--set solver%duration=0.5"
  run_case "${scenario}_two" 0
  run_case "${scenario}_one" 0
  extra_args=""
  if [ -f "$work/${scenario}_one.h5" ] && [ -f "$work/${scenario}_two.h5" ]; then
    h5diff "$work/${scenario}_one.h5" "$work/${scenario}_two.h5" "$dataset" "$dataset" >/dev/null || \
      fail "${scenario}_one: $dataset differs from the two-file run"
  fi
done

# geometry groups twice, or unused
{ cat "$work/two_files.nml" | sed "s|output = .*|output = 'both.h5'|"
  sed -e '/^&run/,/^\//d' -e '/^&grid/,/^\//d' "$root/inputs/demo_slide/slide.nml"; } > "$work/both.nml"
run_case both 1 'both.nml' "geometry_file = '$root/inputs/demo_slide/slide.nml'" 'not both'
printf "&run output = 'unused.h5' /\n&surface kind = 'plane' /\n&point_mass du0 = 1.0 /\n&cross_section radius = 0.5 /\n" > "$work/unused.nml"
run_case unused 1 'unused.nml:4: &cross_section is read only by a tube' "kind = 'plane' (unused.nml:2)"
printf "&run output = 'missing.h5' /\n&surface kind = 'slide' /\n" > "$work/missing.nml"
run_case missing 1 'missing.nml:2:' "kind = 'slide'" 'needs its geometry: &slide_elements'
{ printf "&run scenario = 'geometry', output = 'kind_clash.h5' /\n&geometry kind = 'tube' /\n"; } > "$work/kind_clash.nml"
printf "&run output = 'kind_clash.h5' /\n&surface kind = 'slide' /\n&geometry kind = 'tube' /\n&slide_elements n_elements = 1, kind = 'straight', length = 5.0, slope_deg = 5.0 /\n&point_mass du0 = 1.0 /\n" > "$work/kind_clash.nml"
run_case kind_clash 1 'kind_clash.nml:3:' '&geometry' "kind = 'tube'" "&surface kind = 'slide'"

# centerline points from a CSV file (with horizon vectors), same as inline points
cat > "$work/points.csv" <<'CSV'
# the centerline of inputs/geometry/points_tube.nml
x, y, z, hx, hy, hz
0.0, 0.0, 0.0, 0.0, 0.0, 1.0
2.0, 0.0, -0.2, 0.0, 0.1, 1.0
4.0, 1.0, -0.4, 0.0, 0.2, 1.0
6.0, 3.0, -0.6, -0.2, 0.2, 1.0
7.0, 5.0, -0.8, -0.3, 0.1, 1.0
7.5, 7.0, -1.0, -0.3, 0.0, 1.0
CSV
sed -e "s|output = .*|output = 'inline_points.h5'|" "$root/inputs/geometry/points_tube.nml" > "$work/inline_points.nml"
run_case inline_points 0
cat > "$work/csv_points.nml" <<'NML'
&run scenario = 'geometry', output = 'csv_points.h5' /
&geometry kind = 'tube' /
&centerline
  kind = 'points', points_file = 'points.csv'
  start_tangent = 1.0, 0.0, -0.1
/
&cross_section kind = 'circle', radius = 0.5 /
NML
run_case csv_points 0
if [ -f "$work/csv_points.h5" ] && [ -f "$work/inline_points.h5" ]; then
  h5diff "$work/csv_points.h5" "$work/inline_points.h5" /geometry/centerline/points /geometry/centerline/points \
    >/dev/null || fail "csv_points: centerline differs from the inline points"
fi
# a bad cell is named with file, line and column
sed -e 's/^4.0, 1.0, -0.4,/4.0, 1.0, NaN,/' "$work/points.csv" > "$work/bad_points.csv"
sed -e "s|points.csv|bad_points.csv|" -e "s|csv_points.h5|bad_cell.h5|" "$work/csv_points.nml" > "$work/bad_cell.nml"
run_case bad_cell 1 'bad_cell.nml' "points_file = 'bad_points.csv'" 'bad_points.csv:5: column 3' "'NaN' is not allowed"
sed -e 's/^6.0, 3.0, -0.6, -0.2, 0.2, 1.0/6.0, 3.0, -0.6/' "$work/points.csv" > "$work/ragged.csv"
sed -e "s|points.csv|ragged.csv|" -e "s|csv_points.h5|ragged.h5|" "$work/csv_points.nml" > "$work/ragged.nml"
run_case ragged 1 'ragged.csv:6: has 3 columns, the lines before it 6'
sed -e "s|points.csv|no_such.csv|" -e "s|csv_points.h5|no_csv.h5|" "$work/csv_points.nml" > "$work/no_csv.nml"
run_case no_csv 3 'no_such.csv' 'does not exist'

finish
