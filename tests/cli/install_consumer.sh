#!/usr/bin/env bash
# cmake --install into a fresh prefix, then a project outside the tree
# (tests/install/consumer) finds slidesim with find_package, links
# slidesim::slidesim, and its program (using a geometry, a base and an io
# module) runs; the same program also builds with pkg-config's flags; the
# project configures without tests and benchmarks.
set -u
slidesim=$1
root=$(pwd)
build=$(dirname "$slidesim")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $1"; exit 1; }
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
[ -x "$work/prefix/bin/slidesim" ] || fail "slidesim command not installed"
[ -f "$work/prefix/include/slidesim/geometry_surface.mod" ] || fail "Fortran modules not installed"
[ -f "$work/prefix/include/slidesim/fitpack_interfaces.mod" ] || fail "fitpack modules not installed"
ls "$work/prefix/include/slidesim" | grep -qE '^(testing|fitpack_reference_io|element_checks)\.mod$' \
  && fail "test support modules installed"
"$work/prefix/bin/slidesim" --version | grep -q slidesim || fail "installed slidesim does not run"
cmake -S "$root/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "find_package(slidesim)"; }
cmake --build "$work/consumer" >"$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building against slidesim::slidesim"; }
(cd "$work" && "$work/consumer/consumer" "$work/consumer.h5") | grep -q 'consumer ok' || fail "the consumer program"
[ -f "$work/consumer.h5" ] || fail "the consumer's result file"
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
pkg-config --exists slidesim || fail "pkg-config does not find slidesim.pc"
# shellcheck disable=SC2046
gfortran -o "$work/consumer_pc" "$root/tests/install/consumer/consumer.f90" $(pkg-config --cflags --libs slidesim) \
  >"$work/pc.log" 2>&1 || { cat "$work/pc.log"; fail "building with pkg-config's flags"; }
(cd "$work" && "$work/consumer_pc" "$work/consumer_pc.h5") | grep -q 'consumer ok' || fail "the pkg-config consumer program"
# the options to leave tests and benchmarks out (configure only: no test or bench target)
cmake -S "$root" -B "$work/lean" -DSLIDESIM_BUILD_TESTS=OFF -DSLIDESIM_BUILD_BENCH=OFF >"$work/lean.log" 2>&1 \
  || { cat "$work/lean.log"; fail "configure with SLIDESIM_BUILD_TESTS=OFF, SLIDESIM_BUILD_BENCH=OFF"; }
cmake --build "$work/lean" --target help | grep -qE '(test_|_bench|fitpack_test)' && fail "test or bench targets without tests"
echo "installed, found by find_package and pkg-config, consumer ran; lean configuration has no tests"
