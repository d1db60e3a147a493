#!/usr/bin/env bash
# A B-spline surface from fewer scattered points than its degree needs is
# refused before any work: exit status 1, no result file, and a message that
# names the input line, the geometry file and its &bspline, the point count,
# the degree and the least count ((kx + 1)(ky + 1) for SURFIT).
set -u
slidesim=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/few.csv" <<'CSV'
x, y, z
0, 0, 0
1, 0, 1
0, 1, 1
CSV
echo "&bspline file = 'few.csv', layout = 'scattered', degree = 5, smoothing = 0.05 /" > "$work/few.geo"
cat > "$work/few.nml" <<'NML'
&run scenario = 'contact', output = 'few.h5' /
&shape name = 'table', kind = 'plane' /
&shape name = 'bowl', kind = 'bspline', geometry_file = 'few.geo' /
&body name = 'bowl', mass = 1.0, inertia = 1.0, 1.0, 1.0, position = 0.0, 0.0, 0.5 /
&contact name = 'bowl_on_table', body_1 = 'ground', shape_1 = 'table', body_2 = 'bowl', shape_2 = 'bowl',
  side_1 = 1, side_2 = -1 /
NML
(cd "$work" && "$slidesim" -q few.nml >few.out 2>few.err)
status=$?
failures=0
[ "$status" = 1 ] || { echo "FAIL: exit status $status, expected 1"; failures=$((failures + 1)); }
for needle in 'few.nml:3' '&shape' 'few.geo' '&bspline' '3 data points' 'degree 5 x 5' 'at least 36'; do
  grep -qF -- "$needle" "$work/few.err" || { echo "FAIL: message lacks '$needle'"; failures=$((failures + 1)); }
done
if ls "$work"/*.h5* >/dev/null 2>&1; then echo "FAIL: a result file was written"; failures=$((failures + 1)); fi
if [ "$failures" != 0 ]; then echo "message: $(cat "$work/few.err")"; exit 1; fi
echo "bspline_too_few_points: 9 checks, 0 failed"
