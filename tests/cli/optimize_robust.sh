#!/usr/bin/env bash
# Robust design over a population (issue 29 point 4; docs/design.md, "Robust
# design over a population"), through the command, on a shortened
# inputs/design/optimize_robust.nml (10 members: the five bodies at two
# speeds from straight ahead; two starts; loose tolerances, no constraint,
# so the run is short and ends as an optimum):
# - 1 thread and 2 threads give the same result file, every object to the
#   bit apart from provenance, CPU time and the input's text (its threads)
#   (h5diff -r), and the same summary
#   JSON apart from the CPU time;
# - the summary names the worst member at the end, and the file's
#   /optimize/after/worst_ride is the member of the largest acceleration;
#   the cost's statistic equals that member's acceleration (worst case);
# - the refused variables of &sweep and &optimize: exit 1, each named.
set -u
slidesim=$1
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

short=(--set "sweep%heading0_deg=0" --set optimize%starts=2 --set optimize%ftol=0.1 --set optimize%xtol=0.1
       --set "optimize%constraint='none'")
for threads in 1 2; do
  (cd "$root" && "$slidesim" -q -o "$work/t$threads.h5" --summary-json "$work/t$threads.json" "${short[@]}" \
     --set optimize%threads=$threads inputs/design/optimize_robust.nml >"$work/t$threads.out" 2>"$work/t$threads.err")
  rc=$?
  [ "$rc" = 0 ] || fail "threads = $threads: exit status $rc: $(cat "$work/t$threads.err")"
done

# the objects of two result files that differ, but for provenance, CPU time and the input text
differing() {
  h5diff -r "$1" "$2" >"$work/diff.txt" 2>&1
  awk '
    /^(attribute|dataset|group|datatype): / { object = $0; next }
    /^[0-9]+ differences? found/ {
      if ($1 > 0 && object !~ /<(git_commit|created_utc|compiler|compiler_options|REFERENCE_LIST|input_sha256) of / &&
          object !~ /(cpu_time|\/input\/namelist)>/) print object
      next
    }
    /Not comparable|exist only|not found|Some objects are not comparable/ { print }
  ' "$work/diff.txt"
}

if [ -f "$work/t1.h5" ] && [ -f "$work/t2.h5" ]; then
  unexpected=$(differing "$work/t1.h5" "$work/t2.h5")
  [ -z "$unexpected" ] || fail "1 and 2 threads differ: $unexpected"
  grep -q '^dataset: </optimize/population/height>' "$work/diff.txt" || fail "h5diff did not compare the population"
  "$python" - "$work/t1.json" "$work/t2.json" <<'PY' || fail "the summaries of 1 and 2 threads differ"
import json, sys
a, b = (json.load(open(p))['values'] for p in sys.argv[1:])
for d in (a, b):
    d.pop('cpu_time', None)
sys.exit(a != b)
PY
  "$python" - "$work/t1.h5" <<'PY' || fail "the worst member in the file"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], 'r') as f:
    g = f['/optimize']
    a = g['after/max_acceleration'][()]
    worst = int(g['after/worst_ride'][()])
    ok = (len(a) == 10 and worst == int(np.argmax(a)) + 1 and g['after/robust_acceleration'][()] == a.max()
          and str(g.attrs['population_cost']) == 'worst' and len(g['population/mass']) == 10)
    sys.exit(not ok)
PY
  grep -q '^  worst ride, optimum *member [0-9]* (height ' "$work/t1.out" || fail "the summary does not name the worst member"
  grep -q '^  population (&sweep) *10 members' "$work/t1.out" || fail "the summary does not give the population"
fi

# two MPI ranks (each rides its share of every design's rides): the same file as one process
if [ -f "$work/t1.h5" ] && command -v mpirun >/dev/null 2>&1 && ldd "$slidesim" | grep -q libmpi; then
  (cd "$root" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    mpirun --oversubscribe -n 2 "$slidesim" -o "$work/ranks.h5" "${short[@]}" --set optimize%threads=1 \
    inputs/design/optimize_robust.nml >"$work/ranks.out" 2>"$work/ranks.err")
  rc=$?
  if [ "$rc" = 0 ]; then
    unexpected=$(differing "$work/t1.h5" "$work/ranks.h5")
    [ -z "$unexpected" ] || fail "one process and two MPI ranks differ: $unexpected"
    [ "$(grep -c 'slidesim optimize' "$work/ranks.out")" = 1 ] || fail "two MPI ranks: not one summary (rank 0 reports)"
    cat "$work/ranks.out" "$work/ranks.err" | grep -q '2 MPI ranks' || fail "two MPI ranks: the progress does not say so"
  else
    fail "two MPI ranks: exit status $rc: $(cat "$work/ranks.err")"
  fi
else
  echo "note: no MPI in this build (or no mpirun): the two-rank run is not tested"
fi

# refused: each variable named, exit status 1, nothing written
refused() {   # WHAT EXPECTED-TEXT --set ...
  local what=$1 text=$2
  shift 2
  (cd "$root" && "$slidesim" -q -o "$work/refused.h5" "$@" inputs/design/optimize_robust.nml >"$work/r.out" 2>"$work/r.err")
  local rc=$?
  [ "$rc" = 1 ] || fail "$what: exit status $rc, expected 1"
  grep -q -- "$text" "$work/r.err" || fail "$what: message $(cat "$work/r.err")"
  [ ! -e "$work/refused.h5" ] || fail "$what: a result file was written"
}
refused mu "&sweep: mu = 0.1 is not allowed: not a variable of the optimiser's body" --set sweep%mu=0.1
refused flow_rate "&sweep: flow_rate = 0.004 is not allowed" --set sweep%flow_rate=0.004
refused threads "&sweep: threads = 2 is not allowed: the sweep's run settings" --set sweep%threads=2
refused angles "start_angles_deg = 0 is not allowed: with &sweep heading0_deg" --set optimize%start_angles_deg=0
refused heading "heading0_deg = 95 is not allowed" --set sweep%heading0_deg=95
refused quantile "quantile = 0.5 is not allowed: quantile is the q of population_cost = 'quantile' only" \
  --set optimize%quantile=0.5
refused cost "population_cost" --set "optimize%population_cost='median'"
refused members "give at least 3 members for 5 design variables" --set "sweep%mass=70" --set "sweep%height=1.7" \
  --set "sweep%speed0=0.5" --set "sweep%heading0_deg=0"

[ "$failures" = 0 ] && echo "optimize_robust: all checks passed"
[ "$failures" = 0 ]
