# The set-up of the command-line tests that count their own checks (sourced,
# not a test itself; tests run from the repository root):
#   root      the repository root
#   work      a fresh folder, removed at exit (kept with KEEP=1)
#   check CONDITION MESSAGE   evaluates CONDITION, prints "FAIL MESSAGE" when
#             it fails; counted in $checks and $failures
#   py        a Python 3 (Debian's, which has h5py, when there)
#   ride_with_limits INPUT QUANTITIES UNITS MINS MAXES   rides INPUT (a path
#             from the root) with those &rider limits into $work/NAME.h5,
#             .json (--summary-json), .out and .err, NAME the input's base
#             name, and checks its exit status 0 ($got)
#   check_refused NAME WORDS ARGS...   `slidesim -q --check ARGS` (run in
#             $work) ends with exit status 1 (bad input) and a message on
#             stderr holding WORDS ($work/NAME.err)
# The caller sets slidesim (the command) first.
set -u
root=$(pwd)
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
failures=0; checks=0
check() { checks=$((checks + 1)); if ! eval "$1"; then echo "FAIL $2"; failures=$((failures + 1)); fi; }
py=/usr/bin/python3; [ -x "$py" ] || py=python3

ride_with_limits() {
  local name
  name=$(basename "$1" .nml)
  (cd "$root" && "$slidesim" -o "$work/$name.h5" --summary-json "$work/$name.json" \
    --set "rider%limit_quantity=$2" --set "rider%limit_unit=$3" \
    --set "rider%limit_min=$4" --set "rider%limit_max=$5" \
    "$1" >"$work/$name.out" 2>"$work/$name.err"); got=$?
  check '[ $got = 0 ]' "$name: exit status $got ($(cat "$work/$name.err"))"
}

check_refused() {
  local name=$1 words=$2 got
  shift 2
  (cd "$work" && "$slidesim" -q --check "$@" >"$name.out" 2>"$name.err"); got=$?
  check '[ $got = 1 ]' "$name: exit status $got, expected 1: $(cat "$work/$name.err")"
  check 'grep -qF -- "$words" "$work/$name.err"' "$name: the message lacks '$words': $(cat "$work/$name.err")"
}
