#!/usr/bin/env bash
# Configures and builds slidesim in build/ (Release). Extra arguments go to cmake's
# configure step, e.g. -DCMAKE_BUILD_TYPE=Debug. SLIDESIM_BUILD_TARGETS (e.g.
# "slidesim") builds only those targets; default: everything.
#
# SLIDESIM_PROGRAM_ONLY=1 (scripts/run.sh) builds the slidesim program alone: a
# new build folder is configured for it (-DSLIDESIM_PROGRAM_ONLY=ON, quick to
# build, CMakeLists.txt); a folder configured before is used as it is (a full
# build holds the same program). Without it, a folder configured for the
# program alone is configured again for everything (tests, benchmarks), which
# compiles the layers once more: the tests need their plain code.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLIDESIM_BUILD_DIR:-$root/build}
targets=()
for target in ${SLIDESIM_BUILD_TARGETS:-}; do
  targets+=(--target "$target")
done
scope=()
if [ -n "${SLIDESIM_PROGRAM_ONLY:-}" ]; then
  [ -f "$build/CMakeCache.txt" ] || scope=(-DSLIDESIM_PROGRAM_ONLY=ON)
  targets=(--target slidesim)
else
  if grep -q '^SLIDESIM_PROGRAM_ONLY:BOOL=ON$' "$build/CMakeCache.txt" 2>/dev/null; then
    echo "$build was configured for the slidesim program only (scripts/run.sh):" \
      "configuring it for everything" >&2
  fi
  scope=(-DSLIDESIM_PROGRAM_ONLY=OFF)
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=${SLIDESIM_BUILD_TYPE:-Release} "${scope[@]}" "$@" >/dev/null
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
