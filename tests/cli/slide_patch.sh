#!/usr/bin/env bash
# The free-form patch of issue 26 at the command line (its geometry and
# physics: tests/geometry/test_slide_patch.f90; the shipped inputs run and
# are plotted through cli_every_input and cli_plot_scripts): a patch that
# cannot be built is refused naming the file (and line), the group, the
# value and why (exit 1, no file); a missing patch file is exit 3; the
# rider and the water start on the patch.
slidesim=$1
. "$(dirname "$0")/support/checks.sh"
refused() {   # NAME STATUS EXPECTED TEXT
  local name=$1 status=$2 expected=$3
  printf '%s\n' "$4" >"$work/$name.nml"
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$name.nml" >"$name.out" 2>"$name.err"); local got=$?
  check '[ $got = $status ]' "$name: exit status $got, expected $status ($(cat "$work/$name.err"))"
  check 'grep -qF -- "$expected" "$work/$name.err"' "$name: message lacks '$expected': $(cat "$work/$name.err")"
  check '! ls "$work/$name".h5* >/dev/null 2>&1' "$name: a result file (or a temporary one) was written"
}
# a 6 x 6 grid: a dent of the floor, 0 on the border
grid() {   # FILE [OFFSET AT STATION 0, ANGLE 90]
  { echo 'station, angle, offset'
    for x in 0 2 4 6 8 10; do for a in 50 70 90 110 130 150; do
      d=0
      case "$x,$a" in 4,90 | 6,90) d=-0.05 ;; 0,90) d=${2:-0} ;; esac
      echo "$x, $a, $d"
    done; done; } >"$work/$1"
}
grid good.csv
grid border.csv 0.02
grep -v '^6, 110' "$work/good.csv" >"$work/missing.csv"
{ cat "$work/good.csv"; echo '4, 90, -0.04'; } >"$work/twice.csv"
sed 's/^2, 70, 0$/2, 70, x/' "$work/good.csv" >"$work/word.csv"
elements="&run scenario = 'geometry' /
&geometry kind = 'slide' /
&cross_section kind = 'circle', radius = 0.5 /
&slide_elements n_elements = 3, kind = 'straight', 'patch', 'straight', length = 5, 10, 5,
  slope_deg = 8, 3, 6, centerline_kind = 'exact'"
refused patch_border 1 "patch_file(2) = 'border.csv': the offset at station 0 m, angle 90 deg is 0.02 m: on the border of the grid" \
"$elements, patch_file(2) = 'border.csv' /"
refused patch_missing 1 "missing.csv: no offset at station 6.0 m, angle 110.0 deg: the points must fill the grid" \
"$elements, patch_file(2) = 'missing.csv' /"
refused patch_twice 1 "twice.csv:38: station 4.0 m, angle 90.0 deg is given already on line 16" \
"$elements, patch_file(2) = 'twice.csv' /"
refused patch_word 1 "word.csv:9: column 3: 'x' is not allowed" \
"$elements, patch_file(2) = 'word.csv' /"
refused patch_long 1 "patch_file(2) = 'good.csv': stations from 0 to 10 m: they must lie on the element, in [0, 8] m" \
"${elements/length = 5, 10, 5/length = 5, 8, 5}, patch_file(2) = 'good.csv' /"
refused patch_none 1 "&slide_elements: patch_file(2) = '' is not allowed: a patch needs the CSV file of its offsets" \
"$elements /"
refused patch_other 1 "&slide_elements: patch_file(1) = 'good.csv' is not allowed: a straight has no patch" \
"$elements, patch_file(1) = 'good.csv', patch_file(2) = 'good.csv' /"
refused patch_radius 1 "&slide_elements: radius(2) = 1.0 is not allowed: a patch does not use radius" \
"$elements, patch_file(2) = 'good.csv', radius = 0, 1, 0 /"
refused patch_nofile 3 "no_such.csv" \
"$elements, patch_file(2) = 'no_such.csv' /"
# the good grid builds (exit 0)
printf '%s\n' "$elements, patch_file(2) = 'good.csv' /" >"$work/patch_good.nml"
(cd "$work" && "$slidesim" -q -o good.h5 patch_good.nml >good.out 2>&1); got=$?
check '[ $got = 0 ]' "a good patch: exit $got: $(cat "$work/good.out")"
# the rider's and the water's start on the shipped patch (the rider in the
# middle of the patch, at the bottom; the water a band there)
(cd "$work" && "$slidesim" --check --set rider%u0=28 --set water%u0=28 "$root/inputs/parts/patch.nml" \
  >patch_check.out 2>&1); got=$?
check '[ $got = 0 ] && grep -q "input ok" "$work/patch_check.out"' "rider start on the patch: exit $got: $(cat "$work/patch_check.out")"
printf "&run scenario = 'water', output = 'patch_water.h5' /\n&surface kind = 'slide', geometry_file = '%s' /\n%s\n" \
  "$root/inputs/parts/patch_slide.nml" \
  "&water flow_rate = 0.004, start = 'edges', u0 = 28.0, v_left0 = 1.9, v_right0 = 1.2415926535897932 /" \
  >"$work/patch_water.nml"
(cd "$work" && "$slidesim" patch_water.nml >patch_water.out 2>&1); got=$?
check '[ $got = 0 ] && grep -q "stopped at *end of slide" "$work/patch_water.out"' \
  "water start on the patch: exit $got: $(cat "$work/patch_water.out")"
echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
