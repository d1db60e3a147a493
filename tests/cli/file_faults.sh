#!/usr/bin/env bash
# Files and exit statuses that never lie (issue 12): a full disk (the file-size
# limit), a read-only folder, the input as output, two runs on one output
# path, and kill -9 during a run and during the write each leave either the
# old file or a complete new one under the final name (only a temporary
# <out>.<pid>.XXXXXX.tmp may be broken) and report the truth.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

ellipsoid="$root/inputs/point_mass/ellipsoid.nml"
umask 022

# a result file has the permissions of any new file (the temporary file's
# 0600 is not kept)
run_one() { (cd "$work" && "$slidesim" -q "$@" > /dev/null 2>&1); }
run_one "$ellipsoid" -o plain.h5 || fail "plain run failed"
[ "$(stat -c %a "$work/plain.h5" 2>/dev/null)" = 644 ] || fail "result file mode $(stat -c %a "$work/plain.h5"), not 644"

# the file-size limit (what a full disk does to writes): exit 3, the message,
# no file and no temporary left, no signal
for limit in 8 40; do
  checks=$((checks + 1))
  (ulimit -f $limit; cd "$work" && "$slidesim" "$ellipsoid" -o full.h5 > full.out 2> full.err); got=$?
  [ $got = 3 ] || fail "file-size limit $limit KB: exit status $got, expected 3: $(head -c 300 "$work/full.err")"
  grep -q 'File too large' "$work/full.err" || fail "file-size limit $limit KB: message lacks the reason"
  grep -q 'none: full.h5 could not be written' "$work/full.out" || fail "file-size limit $limit KB: summary names a file"
  ls "$work"/full.h5* >/dev/null 2>&1 && fail "file-size limit $limit KB: files left: $(ls "$work"/full.h5*)"
done

# a real full disk: a small tmpfs (in a mount namespace of our own, where
# the system allows one), its size stepped through the sizes at which each
# part of the file is written (datasets, the status, the XDMF view): every
# run ends with exit 0 and a complete new pair (.h5, .xmf) or exit 3 with
# the old pair untouched, no temporary left, the reason named
cat > "$work/full_disk.sh" <<'SH'
set -u
slidesim=$1 dir=$2 input=$3 output=$4 from=$5 to=$6 step=$7
log=$dir.log   # the messages outside the full disk
mount -t tmpfs -o size=4m tmpfs "$dir" || exit 97
cd "$dir"
cp "$input" run.nml
"$slidesim" -q -o "$output" --set solver%duration=0.1 run.nml > /dev/null 2>&1 || { echo "FAIL old run"; exit 0; }
old=$(cat "$output" "${output%.h5}.xmf" | sha256sum)
used=$(du -sk . | cut -f1)
for k in $(seq $((used + from)) "$step" $((used + to))); do
  mount -o remount,size=${k}k "$dir"
  "$slidesim" -q -o "$output" run.nml > "$log.out" 2> "$log.err"; got=$?
  case $got in
    0) h5dump -a /status "$output" 2>/dev/null | grep -q '"complete"' || echo "FAIL ${k}k: exit 0, file not complete"
       old=$(cat "$output" "${output%.h5}.xmf" | sha256sum) ;;   # the pair the next run must keep or replace
    3) [ "$(cat "$output" "${output%.h5}.xmf" | sha256sum)" = "$old" ] || echo "FAIL ${k}k: exit 3 and the old pair changed"
       grep -q 'No space left on device' "$log.err" || echo "FAIL ${k}k: exit 3 without the reason: $(cat "$log.err")" ;;
    *) echo "FAIL ${k}k: exit status $got: $(tail -c 300 "$log.err")" ;;
  esac
  ls ./*.tmp >/dev/null 2>&1 && { echo "FAIL ${k}k: temporary left: $(ls ./*.tmp)"; rm -f ./*.tmp; }
  echo "ran ${k}k $got"
done
SH
mkdir "$work/tmpfs"
if unshare -m true 2>/dev/null && unshare -m mount -t tmpfs -o size=64k tmpfs "$work/tmpfs" 2>/dev/null; then
  for spec in "$ellipsoid:pm.h5:0:1200:100" "$root/inputs/geometry/helix_tube.nml:helix.h5:0:1800:150" \
              "$root/inputs/sled/bowl.nml:sled.h5:0:1800:150"; do
    IFS=: read -r input output from to step <<< "$spec"
    checks=$((checks + 1))
    # (the geometry run has no &solver: its old run is the same run)
    [ "$output" = helix.h5 ] && sed -i 's/--set solver%duration=0.1 //' "$work/full_disk.sh"
    result=$(unshare -m bash "$work/full_disk.sh" "$slidesim" "$work/tmpfs" "$input" "$output" "$from" "$to" "$step")
    grep '^FAIL' <<< "$result" | while read -r line; do echo "$line ($output)"; done
    failures=$((failures + $(grep -c '^FAIL' <<< "$result")))
    exits=$(grep '^ran' <<< "$result" | awk '{print $3}' | sort -u | tr '\n' ' ')
    case $exits in *0*3*|*3*0*) ;; *) fail "full disk ($output): the sizes tried gave exit statuses '$exits', not both 0 and 3" ;; esac
  done
else
  echo "note: no mount namespace here (unshare -m), the small tmpfs case is not testable"
fi

# a folder we may not write in (not testable as root: root writes anyway)
mkdir "$work/readonly"; chmod 555 "$work/readonly"
if ! touch "$work/readonly/probe" 2>/dev/null; then
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$ellipsoid" -o readonly/x.h5 > ro.out 2> ro.err); got=$?
  [ $got = 3 ] || fail "read-only folder: exit status $got, expected 3"
  grep -q 'readonly/x.h5: cannot write the result file: Permission denied' "$work/ro.err" || \
    fail "read-only folder: message: $(cat "$work/ro.err")"
  [ -z "$(ls "$work/readonly")" ] || fail "read-only folder: files left"
else
  echo "note: running as root, the read-only folder case is not testable here"; rm -f "$work/readonly/probe"
fi
chmod 755 "$work/readonly"
# a folder nobody may create files in, also for root: /sys
if [ -d /sys ] && ! touch /sys/slidesim_probe 2>/dev/null; then
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$ellipsoid" -o /sys/slidesim_test.h5 > sys.out 2> sys.err); got=$?
  [ $got = 3 ] || fail "unwritable folder /sys: exit status $got, expected 3"
  grep -q '/sys/slidesim_test.h5: cannot write the result file' "$work/sys.err" || \
    fail "unwritable folder /sys: message: $(cat "$work/sys.err")"
fi

# the output must not be the input
cp "$ellipsoid" "$work/self.nml"
before=$(sha256sum < "$work/self.nml")
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q self.nml -o ./self.nml > self.out 2> self.err); got=$?
[ $got = 1 ] || fail "output = input (-o): exit status $got, expected 1"
grep -q 'would overwrite the input file' "$work/self.err" || fail "output = input (-o): message: $(cat "$work/self.err")"
sed -e "s|output = .*|output = 'self2.nml'|" "$ellipsoid" > "$work/self2.nml"
before2=$(sha256sum < "$work/self2.nml")
run_case self2 1 'self2.nml:' '&run: output' 'would overwrite the input file'
[ "$(sha256sum < "$work/self.nml")" = "$before" ] && [ "$(sha256sum < "$work/self2.nml")" = "$before2" ] || \
  fail "output = input: the input was changed"

# two runs on one output path at once: both report success, the file is a
# complete one of the two, no temporary left
sed -e "s|scenario = 'point_mass'|scenario = 'point_mass', title = 'run A'|" -e 's|duration = .*|duration = 200.0, output_step = 0.1|' "$ellipsoid" \
  > "$work/a.nml"
sed -e "s|scenario = 'point_mass'|scenario = 'point_mass', title = 'run B'|" -e 's|duration = .*|duration = 200.0, output_step = 0.1|' "$ellipsoid" \
  > "$work/b.nml"
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q a.nml -o same.h5 > a.out 2> a.err) & pid_a=$!
(cd "$work" && "$slidesim" -q b.nml -o same.h5 > b.out 2> b.err) & pid_b=$!
wait $pid_a; got_a=$?; wait $pid_b; got_b=$?
[ $got_a = 0 ] && [ $got_b = 0 ] || fail "two runs on one path: exit statuses $got_a and $got_b: $(cat "$work/a.err" "$work/b.err")"
check_files same 0
title=$(h5dump -a /title "$work/same.h5" 2>/dev/null | grep -o '"run [AB]"')
[ -n "$title" ] || fail "two runs on one path: the file is neither run's"

# kill -9 during the run and during the write: the old file stays, or a
# complete new one replaced it; only temporaries may be broken
sed -e "s|scenario = 'point_mass'|scenario = 'point_mass', title = 'old'|" -e 's|duration = .*|duration = 2.0|' "$ellipsoid" > "$work/old.nml"
(cd "$work" && "$slidesim" -q old.nml -o kept.h5 > /dev/null 2>&1) || fail "kill: the old run failed"
old_sum=$(sha256sum < "$work/kept.h5")
check_kept() {   # after a kill: the old file or a complete new one
  checks=$((checks + 1))
  if [ "$(sha256sum < "$work/kept.h5")" != "$old_sum" ]; then
    state=$(result_status "$work/kept.h5") || fail "$1: the file under the final name: $state"
    [ "${state%%$'\n'*}" = complete ] || fail "$1: the file under the final name is '$state'"
  fi
  rm -f "$work"/kept.h5.*.tmp   # what a killed run may leave (documented)
}
# a long integration (progress lines every few seconds), killed while it runs:
# rtol 1e-12 over 2e5 s is ~30 s of CPU here (at the default rtol the mass
# reaches the domain's edge at t = 4151 s, a failed run that ended within
# the 0.5 s once CVODE was compiled with optimisation)
sed -e "s|scenario = 'point_mass'|scenario = 'point_mass', title = 'long'|" \
    -e 's|duration = .*|duration = 200000.0, output_step = 1.0, rtol = 1e-12, atol = 1e-12|' "$ellipsoid" \
  > "$work/long.nml"
(cd "$work" && exec "$slidesim" -q long.nml -o kept.h5 > /dev/null 2>&1) & pid=$!
sleep 0.5
checks=$((checks + 1))
kill -0 $pid 2>/dev/null || fail "kill -9 during the run: the run had already ended (make it longer)"
kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
check_kept "kill -9 during the run"
[ "$(sha256sum < "$work/kept.h5")" = "$old_sum" ] || fail "kill -9 during the run: the old file was replaced"
# a large surface grid: most of the time goes to writing it; killed at several moments
printf "&run scenario = 'geometry', output = 'kept.h5' /\n&geometry kind = 'tube' /\n&centerline kind = 'line' /\n&grid n_u = 3000, n_v = 1000 /\n" > "$work/big.nml"
for delay in 0.2 0.6 1.2 2.5; do
  (cd "$work" && exec "$slidesim" -q big.nml > /dev/null 2>&1) & pid=$!
  sleep $delay; kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
  check_kept "kill -9 after $delay s of a large write"
done

finish
