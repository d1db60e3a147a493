#!/usr/bin/env bash
# Standard output that cannot take the summary: a pipe whose reader has gone
# (slidesim ... | head), a closed stream (>&-), a full device (/dev/full).
# The run is not killed part way (SIGPIPE once left the temporary result
# file behind, exit status 141); it ends with exit status 3 and says so on
# standard error, the result file complete under its final name, no
# temporary file left, the summary JSON still written.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

ellipsoid="$root/inputs/point_mass/ellipsoid.nml"

# closed_pipe NAME ARGS...: runs slidesim with standard output (and, with
# NAME both_*, standard error) into a pipe whose reader closed it before
# slidesim started; leaves $work/NAME.rc and $work/NAME.err
closed_pipe() {
  local name=$1; shift
  rm -f "$work/reader_gone"
  if [ "${name#both_}" != "$name" ]; then
    { while [ ! -e "$work/reader_gone" ]; do sleep 0.01; done
      (cd "$work" && exec "$slidesim" "$@" 2>&1); echo $? > "$work/$name.rc"; } |
      { exec 0<&-; touch "$work/reader_gone"; }
    : > "$work/$name.err"   # (the messages went into the pipe too)
  else
    { while [ ! -e "$work/reader_gone" ]; do sleep 0.01; done
      (cd "$work" && exec "$slidesim" "$@" 2>"$work/$name.err"); echo $? > "$work/$name.rc"; } |
      { exec 0<&-; touch "$work/reader_gone"; }
  fi
}

# expect NAME WANT [NEEDLE]: exit status, the message, a complete result file
# NAME.h5, no temporary, the summary JSON NAME.json
expect() {
  local name=$1 want=$2 needle=${3:-} got state
  checks=$((checks + 1))
  got=$(cat "$work/$name.rc" 2>/dev/null || echo none)
  [ "$got" = "$want" ] || fail "$name: exit status $got, expected $want: $(head -c 300 "$work/$name.err")"
  if [ -n "$needle" ]; then
    grep -qF -- "$needle" "$work/$name.err" || fail "$name: message lacks '$needle': $(head -c 300 "$work/$name.err")"
  fi
  if [ ! -f "$work/$name.h5" ]; then
    fail "$name: no result file"
  else
    state=$(result_status "$work/$name.h5") || fail "$name: $state"
    [ "${state%%$'\n'*}" = complete ] || fail "$name: the result file is '$state', not complete"
  fi
  [ -s "$work/$name.json" ] || fail "$name: no summary JSON"
  if ls "$work"/*.tmp >/dev/null 2>&1; then
    fail "$name: temporary file left: $(ls "$work"/*.tmp)"
    rm -f "$work"/*.tmp
  fi
}

# a reader that has gone: standard output only, then both streams (the
# progress message on standard error comes while the result file is open)
closed_pipe stdout_pipe "$ellipsoid" -o stdout_pipe.h5 --summary-json stdout_pipe.json
expect stdout_pipe 3 'cannot write to standard output: Broken pipe'
closed_pipe both_pipe "$ellipsoid" -o both_pipe.h5 --summary-json both_pipe.json
expect both_pipe 3

# standard output closed, and a full device
(cd "$work" && "$slidesim" "$ellipsoid" -o closed.h5 --summary-json closed.json >&- 2>closed.err); echo $? > "$work/closed.rc"
expect closed 3 'standard output is closed'
(cd "$work" && "$slidesim" "$ellipsoid" -o full.h5 --summary-json full.json >/dev/full 2>full.err); echo $? > "$work/full.rc"
expect full 3 'No space left on device'

# the same run with standard output readable: exit 0 (the check above is
# about the stream, not the run)
(cd "$work" && "$slidesim" "$ellipsoid" -o fine.h5 --summary-json fine.json >fine.out 2>fine.err); echo $? > "$work/fine.rc"
expect fine 0
grep -q 'results                   fine.h5' "$work/fine.out" || fail "fine: the summary lacks its results line"

# what is printed without a run: --check, --help, --default-input
for args in "--check $ellipsoid" --help --default-input; do
  checks=$((checks + 1))
  # shellcheck disable=SC2086
  (cd "$work" && "$slidesim" $args >/dev/full 2>option.err); got=$?
  [ $got = 3 ] || fail "slidesim $args >/dev/full: exit status $got, expected 3"
  grep -qF 'No space left on device' "$work/option.err" || fail "slidesim $args >/dev/full: message lacks the reason"
done

finish
