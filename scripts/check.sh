#!/usr/bin/env bash
# Installs the dependencies with the test and viewer extras, builds, and runs
# the whole test suite with ctest.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-dependencies.sh" --test
"$root/scripts/build.sh" "$@"
cd "${SLIDESIM_BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$(nproc)"
