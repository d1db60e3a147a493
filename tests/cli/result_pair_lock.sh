#!/usr/bin/env bash
# A result file and its XDMF view are renamed into place under an exclusive
# lock on their folder (flock(2) on the folder itself), so that of two runs
# writing one path the last to rename leaves both of its files: a view never
# reads the other run's result (its arrays are datasets of the .h5 beside it).
# Here this shell holds the folder's lock (util-linux flock) while a run
# finishes: the run must wait with both its temporary files written and
# neither final name present; once the lock is released both appear, the view
# naming the result, exit 0.
set -u
slidesim=$(realpath "$1")
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"
command -v flock >/dev/null || { echo "FAIL flock (util-linux) not found"; exit 1; }
out="$work/out"
mkdir "$out"
exec 9<"$out"
flock -x 9
(cd "$root" && exec "$slidesim" -q -o "$out/flume.h5" inputs/geometry/flume.nml) >"$work/run.out" 2>&1 &
pid=$!
# the run's two temporary files (the result and its view) exist once it waits to rename them
for _ in $(seq 600); do
  [ "$(find "$out" -name '*.tmp' | wc -l)" = 2 ] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
sleep 1
checks=$((checks + 1))
if ! kill -0 "$pid" 2>/dev/null; then
  fail "the run ended while this shell held its folder's lock: $(ls "$out")"
elif [ -e "$out/flume.h5" ] || [ -e "$out/flume.xmf" ]; then
  fail "a final name appeared while the folder was locked: $(ls "$out")"
fi
flock -u 9
exec 9<&-
wait "$pid"
rc=$?
checks=$((checks + 1))
[ "$rc" = 0 ] || fail "exit $rc: $(cat "$work/run.out")"
checks=$((checks + 1))
[ -f "$out/flume.h5" ] && [ -f "$out/flume.xmf" ] || fail "not both files after the lock was released: $(ls "$out")"
checks=$((checks + 1))
grep -q '>flume.h5:/' "$out/flume.xmf" || fail "the view does not read flume.h5"
checks=$((checks + 1))
[ -z "$(find "$out" -name '*.tmp')" ] || fail "a temporary file left: $(ls "$out")"
echo "$checks checks, $failures failures"
[ "$failures" = 0 ]
