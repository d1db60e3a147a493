#!/usr/bin/env bash
# Configures and builds slidesim in build/ (Release). Extra arguments go to cmake's
# configure step, e.g. -DCMAKE_BUILD_TYPE=Debug. SLIDESIM_BUILD_TARGETS (e.g.
# "slidesim") builds only those targets (scripts/run.sh); default: everything.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLIDESIM_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=${SLIDESIM_BUILD_TYPE:-Release} "$@" >/dev/null
targets=()
for target in ${SLIDESIM_BUILD_TARGETS:-}; do
  targets+=(--target "$target")
done
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
