#!/usr/bin/env bash
# The sweep scenario end to end on a handful of short rides (2.5 s bound):
# one thread, two threads and (when slidesim is built with MPI and mpirun is
# there) two MPI ranks give the same CSV summary and the same /sweep datasets,
# to the bit (all but the wall-clock times); a ride that cannot start and
# rides whose water fails are reported as failed (status and message) while
# the others finish; bad &sweep inputs are refused before any work (exit 1,
# no file), naming the file, the group, the variable, the value and what is
# allowed.
slidesim=$1
repo=$(pwd)   # tests run from the repository root
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
. "$(dirname "$0")/support/checks.sh"

# the demo ride as the base, &solver duration 2.5 s, eight rides: (male 90 kg,
# female 55 kg) paired x start u0 (0.5, 66.5: the heels beyond the end) x
# flow rate (0.004, 0.002: critical at the start)
sed -e "s|'../demo_slide/slide.nml'|'$repo/inputs/demo_slide/slide.nml'|" \
    -e "s|  output_step = 0.01|  output_step = 0.01, duration = 2.5|" -e "s|scenario = 'ride'|scenario = 'sweep'|" "$repo/inputs/ride/demo_slide.nml" >"$work/base.nml"
grep -q 'duration = 2.5' "$work/base.nml" || { echo "FAIL the base input was not shortened"; exit 1; }
sweep() {   # name, threads, extra &sweep lines
  cp "$work/base.nml" "$work/$1.nml"
  printf "&sweep\n  sex = 'male', 'female'\n  mass = 90.0, 55.0\n  paired = 'sex', 'mass'\n  u0 = 0.5, 66.5\n  flow_rate = 0.004, 0.002\n  threads = %s\n%s\n/\n" "$2" "${3:-}" >>"$work/$1.nml"
}
sweep one 1
sweep two 2
(cd "$work" && "$slidesim" -q -o one.h5 one.nml >one.out 2>one.err); got=$?
check '[ $got = 0 ]' "one thread: exit status $got ($(cat "$work/one.err"))"
(cd "$work" && "$slidesim" -q -o two.h5 two.nml >two.out 2>two.err); got=$?
check '[ $got = 0 ]' "two threads: exit status $got ($(cat "$work/two.err"))"
check 'grep -q "threads per rank  *2" "$work/two.out"' "two threads: the summary says 2 threads"
check '[ -f "$work/one.csv" ] && [ -f "$work/two.csv" ]' "the CSV summaries beside the result files"
check '[ "$(wc -l <"$work/one.csv")" = 9 ]' "the CSV: a header and 8 rides"

# what each ride did (flow rate fastest): rides 1, 5 ran to the bound, 3, 7
# cannot start, 2, 4, 6, 8 have critical water
status_of() { awk -F, -v r="$2" 'NR == r + 1 { print $2 }' "$work/$1.csv"; }
for r in 1 5; do check '[ "$(status_of one $r)" = stopped ]' "ride $r: stopped by the bound ($(status_of one $r))"; done
for r in 2 3 4 6 7 8; do check '[ "$(status_of one $r)" = failed ]' "ride $r: failed ($(status_of one $r))"; done
check 'grep -q "^2,failed,.*the water failed.*critical" "$work/one.csv"' "ride 2: why it failed"
check 'grep -q "^3,failed,.*heels cannot reach the slide" "$work/one.csv"' "ride 3: why it failed"
check 'grep -q "^1,stopped,male,90.0,.*had not ended after 2.5 s" "$work/one.csv"' "ride 1: its values and outcome"
check 'grep -q "^5,stopped,female,55.0," "$work/one.csv"' "ride 5: paired female 55 kg"
check 'grep -q "failed  *6" "$work/one.out"' "the summary counts the failed rides"

# ride 1 is the ride scenario's ride of the same input (90 kg), to the bit
sed "s|scenario = 'sweep'|scenario = 'ride'|" "$work/base.nml" >"$work/ride.nml"
(cd "$work" && "$slidesim" -q -o ride.h5 --set rider%mass=90.0 ride.nml >ride.out 2>ride.err); got=$?
check '[ $got = 0 ]' "the ride alone: exit status $got ($(cat "$work/ride.err"))"
check '"$python" -c "
import h5py, sys
s, r = h5py.File(sys.argv[1]), h5py.File(sys.argv[2])
pairs = [(\"top_speed\", \"top_speed\"), (\"felt_normal_max\", \"acceleration_normal_max\"),
         (\"lever_arm_max\", \"lever_arm_max\"), (\"ride_time\", \"ride_time\")]
sys.exit(0 if all(s[\"/sweep/\" + a][0] == r[\"/evaluation/\" + b][()] for a, b in pairs) else 1)
" "$work/one.h5" "$work/ride.h5"' "ride 1 of the sweep = the ride scenario's ride (top speed, felt normal max, lever arm, time)"

# the same results, to the bit, whatever shares them out
same() {   # name a, name b, what
  a=$1; b=$2
  check '"$python" "$repo/tests/cli/support/same_sweep.py" "$work/$a.h5" "$work/$b.h5" "$work/$a.csv" "$work/$b.csv"' \
    "$3: results differ"
}
same one two "one thread vs two threads"
if command -v mpirun >/dev/null 2>&1 && ldd "$slidesim" | grep -q libmpi; then
  sweep ranks 1
  (cd "$work" && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    mpirun --oversubscribe -n 2 "$slidesim" -q -o ranks.h5 ranks.nml >ranks.out 2>ranks.err); got=$?
  check '[ $got = 0 ]' "two MPI ranks: exit status $got ($(cat "$work/ranks.err"))"
  check 'grep -q "MPI ranks  *2" "$work/ranks.out"' "two MPI ranks: the summary says 2 ranks: $(cat "$work/ranks.out")"
  check '[ "$(grep -c "slidesim sweep" "$work/ranks.out")" = 1 ]' "two MPI ranks: one summary (rank 0 writes)"
  same one ranks "one rank vs two MPI ranks"
else
  echo "note: no MPI in this build (or no mpirun): the two-rank run is not tested"
fi

# bad &sweep inputs: nothing run, nothing written
bad() {   # name, &sweep lines, expected message part
  name=$1; expected=$3
  cp "$work/base.nml" "$work/$name.nml"
  printf "&sweep\n%b\n/\n" "$2" >>"$work/$name.nml"
  (cd "$work" && "$slidesim" -q -o "$name.h5" "$name.nml" >"$name.out" 2>"$name.err"); got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1 ($(cat "$work/$name.err"))"
  check 'grep -qF -- "$expected" "$work/$name.err"' "$name: message lacks '$expected': $(cat "$work/$name.err")"
  check '! ls "$work/$name".h5* "$work/$name".csv* >/dev/null 2>&1' "$name: a result or CSV file was written"
}
bad mass_low "  mass = 60.0, 5.0" "mass_low.nml:"
bad mass_low2 "  mass = 60.0, 5.0" "&sweep: mass(2) = 5.0 is not allowed: must be a finite number in [10, 300] (kg)"
bad no_sweep "  threads = 1" "give at least one of sex, mass, height"
bad unknown "  weight = 60.0" 'unknown variable "weight"; allowed: sex mass height'
bad range_count "  height_range = 1.5, 1.9, 0" "&sweep: height_range = 1.5, 1.9, 0 is not allowed: first, last, count: the count must be a whole number in [2, 10000]"
bad paired_counts "  mass = 60.0, 70.0\n  height = 1.7\n  combine = 'paired'" "&sweep: height = 1.7 is not allowed: paired with mass: it needs as many values (2), it has 1"
bad sex_word "  sex = 'boy'" "sex"
bad flow_zero "  flow_rate = 0.004, 0.0" "&sweep: flow_rate(2) = 0.0 is not allowed: must be a finite number in [1.0E-06, 1] (m^3/s)"
# one declaration of flow_rate and f1 for &water and &sweep: the sweep no longer allows what &water refuses
bad flow_high "  flow_rate = 0.004, 2.0" "&sweep: flow_rate(2) = 2.0 is not allowed: must be a finite number in [1.0E-06, 1] (m^3/s)"
bad f1_high "  f1 = 0.03, 2000.0" "&sweep: f1(2) = 2000.0 is not allowed: must be a finite number in [0, 1000] (kg/m)"
bad threads "  mass = 60.0\n  threads = -1" "&sweep: threads = -1 is not allowed: must be a whole number in [0, 1024]"
# a range's first and last have the shared declaration's bounds and no other (was a reader's own -1e6 .. 1e6)
bad f1_range_high "  f1_range = 0.03, 2000, 3" "&sweep: f1_range = 0.03, 2000, 3 is not allowed: first and last: must be a finite number in [0, 1000] (kg/m)"
bad f1_range_far "  f1_range = 0.03, 2e7, 3" "&sweep: f1_range = 0.03, 2e7, 3 is not allowed: first and last: must be a finite number in [0, 1000] (kg/m)"
bad too_many "  mass_range = 50, 100, 10000\n  height_range = 1.5, 1.9, 10000" "at most 1000000 rides"

echo "$checks checks, $failures failed"
[ "$failures" = 0 ]
