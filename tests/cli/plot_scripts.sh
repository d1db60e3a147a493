#!/usr/bin/env bash
# Every plot script runs headless on a result of its scenario and writes a PNG
# (-o); each refuses a result of another scenario and a file that is not a
# result with a message naming the file (exit status 1). Needs Debian's
# python3-matplotlib, -h5py, -numpy (scripts/install-dependencies.sh).
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
unset DISPLAY   # as in CI: no window, the Agg backend
run() { (cd "$root" && "$slidesim" -q -o "$work/$1.h5" "$2" >/dev/null 2>&1) || fail "slidesim $2"; }
run water inputs/water/demo_slide.nml
run slide inputs/demo_slide/slide.nml
run point_mass inputs/point_mass/ellipsoid.nml
run pendulum inputs/pendulum/double.nml
run fourbar inputs/fourbar/crank_rocker.nml
run sled inputs/sled/bowl.nml
for kind in water slide point_mass pendulum fourbar sled; do
  script=$root/scripts/plot_$kind.py
  if ! "$python" "$script" "$work/$kind.h5" -o "$work/$kind.png" >"$work/$kind.out" 2>&1; then
    fail "plot_$kind.py: $(cat "$work/$kind.out")"; continue
  fi
  head -c 8 "$work/$kind.png" | od -An -c | grep -q 'P   N   G' || fail "plot_$kind.py: $kind.png is not a PNG"
  [ "$(stat -c %s "$work/$kind.png")" -gt 20000 ] || fail "plot_$kind.py: $kind.png is almost empty"
  other=water; [ "$kind" = water ] && other=sled
  "$python" "$script" "$work/$other.h5" -o "$work/wrong.png" >"$work/wrong.out" 2>&1
  [ $? = 1 ] || fail "plot_$kind.py accepted a $other result"
  grep -q "a '$other' result" "$work/wrong.out" || fail "plot_$kind.py: no clear message for a $other result: $(cat "$work/wrong.out")"
  "$python" "$script" "$root/README.md" >"$work/text.out" 2>&1
  [ $? = 1 ] && grep -q 'README.md: not an HDF5 file' "$work/text.out" \
    || fail "plot_$kind.py: no clear message for a text file: $(cat "$work/text.out")"
done
echo "6 plot scripts, $failures failures"
[ "$failures" = 0 ]
