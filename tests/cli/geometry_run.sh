#!/usr/bin/env bash
# The geometry scenario on the demo slide writes a complete file with the
# documented datasets and units; the point mass runs on the demo slide.
set -u
slidesim=$1
repo=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

cd "$work" || exit 1
ln -s "$repo/inputs" inputs
"$slidesim" -q inputs/demo_slide/slide.nml -o demo.h5 > out.txt 2> err.txt || fail "geometry run: $(cat err.txt)"
[ -f demo.h5 ] || fail "no demo.h5"
if command -v h5ls > /dev/null && [ -f demo.h5 ]; then
  for d in geometry/surface/x geometry/surface/y geometry/surface/z geometry/surface/u geometry/surface/v \
           geometry/centerline/points geometry/centerline/arc_length geometry/centerline/chi \
           geometry/centerline/chi_u geometry/centerline/frame_x geometry/centerline/frame_y \
           geometry/centerline/frame_z geometry/centerline/length; do
    h5ls "demo.h5/$d" > /dev/null 2>&1 || fail "missing dataset /$d"
  done
  h5dump -a /geometry/centerline/chi/units demo.h5 2>/dev/null | grep -q '"m^-1"' || fail "chi has no units m^-1"
  h5dump -a /status demo.h5 2>/dev/null | grep -q complete || fail "file not marked complete"
  # 60-80 m of slide
  len=$(h5dump -d /geometry/centerline/length demo.h5 | grep -o '(0): [0-9.]*' | cut -d' ' -f2)
  awk -v l="$len" 'BEGIN { exit !(l >= 60 && l <= 80) }' || fail "demo slide length $len m not in [60, 80]"
fi
"$slidesim" -q inputs/demo_slide/point_mass.nml -o pm.h5 > pm.txt 2> pm.err || fail "point mass on demo slide: $(cat pm.err)"
grep -q 'energy balance error' pm.txt || fail "no point-mass summary"
for f in tube_blend_fig3_11 helix_tube flume blend_paraboloids blend_cylinders points_tube bspline_bump; do
  "$slidesim" -q "inputs/geometry/$f.nml" -o "$f.h5" > /dev/null 2> "$f.err" || fail "$f: $(cat "$f.err")"
done
echo "geometry_run: $failures failed"
[ $failures = 0 ]
