#!/usr/bin/env bash
# examples/ride_consumer against an installed slidesim: cmake --install into a
# fresh prefix, the example built once with CMake's find_package(slidesim)
# and once with `pkg-config --cflags --libs slidesim` (it reaches the
# scenario registry, hence the sweep's MPI ranks: slidesim.pc must carry
# MPI's libraries when slidesim is built with MPI), and both programs ride
# the demo slide through run_ride. What they print must be what the
# slidesim command's --summary-json says of the same (default) ride: the
# same outcome, and the top and exit speeds to the last bit (both write
# numbers that read back exactly; the same code on the same input).
set -u
slidesim=$1
root=$(pwd)
build=$(dirname "$slidesim")
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $1"; exit 1; }
example=$root/examples/ride_consumer
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
cmake -S "$example" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" 2>&1 \
  || { cat "$work/configure.log"; fail "find_package(slidesim)"; }
cmake --build "$work/cmake" >"$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building with slidesim::slidesim"; }
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
flags=$(pkg-config --cflags --libs slidesim) || fail "pkg-config does not find slidesim.pc"
# shellcheck disable=SC2086
gfortran -o "$work/ride_consumer_pc" "$example/ride_consumer.f90" $flags >"$work/pc.log" 2>&1 \
  || { cat "$work/pc.log"; fail "building with pkg-config's flags"; }
(cd "$work" && "$slidesim" -q -o "$work/default.h5" --summary-json "$work/default.json" >/dev/null) \
  || fail "slidesim's default ride"
failures=0
for program in "$work/cmake/ride_consumer" "$work/ride_consumer_pc"; do
  (cd "$work" && "$program") >"$work/out" 2>"$work/err" || { cat "$work/out" "$work/err"; fail "$program"; }
  [ -s "$work/err" ] && { echo "FAIL $program wrote to standard error:"; cat "$work/err"; failures=$((failures + 1)); }
  "$python" - "$work/out" "$work/default.json" <<'PY' || { echo "FAIL $program"; failures=$((failures + 1)); }
import json, sys
printed = dict(line.split(': ', 1) for line in open(sys.argv[1]).read().splitlines())
summary = json.load(open(sys.argv[2]))
values = summary['values']
problems = []
if summary['status'] != 'complete' or printed.get('status') != 'ok':
    problems.append(f"status {printed.get('status')!r}, slidesim's {summary['status']!r}")
if printed.get('stopped') != values['outcome']:
    problems.append(f"stopped {printed.get('stopped')!r}, slidesim's outcome {values['outcome']!r}")
for key in ('top_speed', 'exit_speed'):
    if key not in printed:
        problems.append(f'{key} not printed')
        continue
    number, unit = printed[key].split()
    if float(number) != values[key] or unit != 'm/s':
        problems.append(f'{key} {printed[key]}, slidesim says {values[key]!r} m/s')
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
PY
done
[ "$failures" = 0 ] || exit 1
echo "installed; the ride consumer built with find_package and with pkg-config; both gave slidesim's default ride"
