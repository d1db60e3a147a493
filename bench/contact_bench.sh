#!/usr/bin/env bash
# Called by bench/run.sh with the build folder: contact between moving surfaces
# (issue 10). Writes towers of n = 1..N rolling paraboloids into a temporary
# folder (scripts/make_contact_inputs.py) and times them for T simulated
# seconds; SLIDESIM_TOWER_MAX (default 12) and SLIDESIM_TOWER_SECONDS
# (default 10) change N and T.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/support/bench_program.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
towers=$(mktemp -d)
trap 'rm -rf "$towers"' EXIT
files=()
for n in $(seq 1 "${SLIDESIM_TOWER_MAX:-12}"); do
  # --untested: SLIDESIM_TOWER_MAX may ask for towers beyond the tested 12 (a warning then)
  python3 "$root/scripts/make_contact_inputs.py" --tower "$n" --folder "$towers" --untested
  files+=("$towers/tower$n.nml")
done
cd "$root"
contact_bench=$(bench_program "$1" contact_bench)
"$contact_bench" "${SLIDESIM_TOWER_SECONDS:-10}" "${files[@]}"
