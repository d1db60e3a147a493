#!/usr/bin/env bash
# --export-stl and --export-obj (src/io/io_mesh_export.f90), checked by
# tests/cli/check_mesh.py, which parses both formats itself: a straight tube
# (radius 0.5 m, 10 m, n_v = 48) has the area of its inscribed polygon to the
# file's nine digits and falls short of 2 pi r L by the chords' (pi/n)^2/6,
# every triangle faces away from the axis, every interior edge runs once each
# way, the only boundary is the two ends; the demo ride exports its slide
# and its water band (facing up), STL and OBJ alike. Refused: a scenario
# without a surface (exit 1), the result file itself (exit 1), a device
# (a private /dev/full node: exit 3, the node untouched, nothing run).
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
cat >"$work/tube.nml" <<'NML'
&run
  scenario = 'geometry', output = 'tube.h5'
/
&geometry
  kind = 'tube'
/
&centerline
  kind = 'line', start = 0.0, 0.0, 0.0, end = 10.0, 0.0, 0.0
/
&cross_section
  kind = 'circle', radius = 0.5
/
&grid
  n_u = 21, n_v = 48
/
NML
(cd "$work" && "$slidesim" -q tube.nml --export-stl tube.stl --export-obj tube.obj >out 2>&1) \
  || fail "slidesim tube.nml --export-stl --export-obj: $(cat "$work/out")"
"$python" "$root/tests/cli/check_mesh.py" tube "$work/tube.stl" "$work/tube.obj" 0.5 10 48 || fail "the tube's mesh"
"$slidesim" -q -o "$work/ride.h5" --export-stl "$work/ride.stl" --export-obj "$work/ride.obj" >"$work/out" 2>&1 \
  || fail "the default ride with --export-stl --export-obj: $(cat "$work/out")"
"$python" "$root/tests/cli/check_mesh.py" ride "$work/ride.stl" "$work/ride.obj" || fail "the ride's meshes"
ls -a "$work" | grep -q '\.tmp' && fail "a temporary file was left: $(ls -a "$work")"
# refusals, before any work
expect() {   # STATUS WHAT ARGS...: exit status and a message with WHAT
  local status=$1 what=$2
  shift 2
  "$slidesim" -q "$@" >"$work/out" 2>&1
  local rc=$?
  [ "$rc" = "$status" ] || fail "$*: exit status $rc, not $status"
  grep -qF -- "$what" "$work/out" || fail "$*: message without '$what': $(cat "$work/out")"
}
expect 1 "has no surface to export" -o "$work/p.h5" --export-obj "$work/p.obj" "$root/inputs/pendulum/simple.nml"
[ -e "$work/p.h5" ] && fail "a refused export still ran the pendulum"
expect 1 "would be written to the same file as the result file" -o "$work/same.h5" --export-stl "$work/same.h5" "$root/inputs/geometry/flume.nml"
expect 1 "would be written to the same file as the STL export" -o "$work/g.h5" --export-stl "$work/m" --export-obj "$work/m" "$root/inputs/geometry/flume.nml"
if mknod -m 666 "$work/full" c 1 7 2>/dev/null; then
  expect 3 "cannot write the STL export: it is" -o "$work/d.h5" --export-stl "$work/full" "$root/inputs/geometry/flume.nml"
  [ -c "$work/full" ] || fail "the device node was replaced"
  [ -e "$work/d.h5" ] && fail "a refused export still ran"
fi
[ "$failures" = 0 ] && echo "mesh export checks passed"
[ "$failures" = 0 ]
