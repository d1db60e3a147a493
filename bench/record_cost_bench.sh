#!/usr/bin/env bash
# What a run costs through the command, in instructions (callgrind, the same
# on any machine) and process CPU seconds (median of N runs, this machine):
# the default ride (`slidesim -q -o FILE`), inputs/ride/jump.nml and
# inputs/contact/egg.nml, each whole (reading, integration, records, result
# and XDMF files). Prints per run the instructions of the whole process and,
# inclusive, of the XDMF view's moving boxes (`xdmf_moving_box`, the rider's
# bodies), of closing the view (`xdmf_attach`), of gfortran's formatted
# writes (`_gfortran_transfer_array_write` and `_gfortran_transfer_real_write`
# together) and of the dynamics (`kinetostatics_mechanism_MOD_dynamics`:
# right-hand sides, root functions and records), then the CPU median. A
# column is 0 where the run has no such call (link-time optimisation may
# also inline a small function into its caller).
#
#     bash bench/record_cost_bench.sh BUILD [N]     # from anywhere; N = 11
#
# With two builds (e.g. a base and a change) run it once for each and
# compare the lines: callgrind's counts do not depend on the machine's load;
# the CPU medians do (run both builds alternately on a quiet machine).
set -euo pipefail
build=$(cd "${1:?usage: record_cost_bench.sh BUILD [N]}" && pwd)
runs=${2:-11}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
slidesim=$build/slidesim
[ -x "$slidesim" ] || { echo "record_cost_bench: $slidesim is not an executable" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "record_cost_bench: skipped (needs valgrind)"; exit 0; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# inclusive instructions of the functions whose names contain $2 in the
# callgrind output $1 (the largest match: a function's own line)
inclusive() {
  callgrind_annotate --inclusive=yes --threshold=100 "$1" 2>/dev/null |
    awk -v name="$2" 'index($0, name) { gsub(",", "", $1); if ($1 + 0 > best) best = $1 + 0 }
                      END { printf "%.4e", best + 0 }'
}

printf '%-8s %12s %12s %12s %12s %12s %11s\n' run instructions moving_box xdmf_attach formatted dynamics 'CPU median'
for run in default inputs/ride/jump.nml inputs/contact/egg.nml; do
  args=(-q -o "$work/run.h5")
  [ "$run" = default ] || args+=("$root/$run")
  (cd "$work" && valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$slidesim" "${args[@]}" \
    >/dev/null 2>"$work/valgrind.txt")
  total=$(sed -n 's/^summary: //p;s/^totals: //p' "$work/cg.out" | head -1 | awk '{ printf "%.4e", $1 }')
  boxes=$(inclusive "$work/cg.out" 'xdmf_moving_box')
  attach=$(inclusive "$work/cg.out" 'xdmf_attach')
  formatted=$(awk -v a="$(inclusive "$work/cg.out" '_gfortran_transfer_array_write')" \
    -v b="$(inclusive "$work/cg.out" '_gfortran_transfer_real_write')" 'BEGIN { printf "%.4e", a + b }')
  dynamics=$(inclusive "$work/cg.out" 'kinetostatics_mechanism_MOD_dynamics')
  read -r cpu _ < <(cd "$work" && python3 "$root/bench/support/process_cpu.py" "$runs" "$slidesim" "${args[@]}")
  printf '%-8s %12s %12s %12s %12s %12s %9s s\n' "$(basename "$run" .nml)" "$total" "$boxes" "$attach" \
    "$formatted" "$dynamics" "$cpu"
done
