# Shared checks of the command-line tests (sourced, not a test itself): a
# fresh folder $work (removed at exit) and the checks below.
#
# run_case NAME WANT [NEEDLE...]: runs "$slidesim -q [$extra_args] NAME.nml" in
# $work, then checks the exit status WANT, that every NEEDLE appears on stderr,
# and what the documented meaning of the status says about the result file
# $work/NAME.h5 (the input must write there):
#   0  the file exists, is marked complete and holds only finite numbers;
#   1  no file at all (nothing written, no temporary left);
#   2  the file exists and is marked incomplete;
#   3  no temporary file left.
# Every case sets $work/NAME.out and $work/NAME.err; failures are counted.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=${failures:-0}
checks=${checks:-0}
extra_args=${extra_args:-}
here_support=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# a Python 3 that has h5py (Debian's, also when another python3 comes first)
h5python=""
for candidate in python3 /usr/bin/python3; do
  if command -v "$candidate" >/dev/null && "$candidate" -c 'import h5py' 2>/dev/null; then
    h5python=$candidate; break
  fi
done

fail() { echo "FAIL $1"; failures=$((failures + 1)); }

# result_status FILE: prints complete/incomplete; non-zero if a complete file
# holds a non-finite number or the file cannot be read
result_status() {
  if [ -n "$h5python" ]; then
    "$h5python" "$here_support/check_result.py" "$1"
  else
    h5dump -a /status "$1" 2>/dev/null | grep -o '"[a-z]*complete"' | tr -d '"'
  fi
}

# check_files NAME STATUS: the files the documented meaning of STATUS allows
check_files() {
  local name=$1 got=$2 state
  case $got in
    0) if [ ! -f "$work/$name.h5" ]; then fail "$name: exit 0 but no result file"
       else state=$(result_status "$work/$name.h5") || fail "$name: $state"
            [ "${state%%$'\n'*}" = complete ] || fail "$name: exit 0 but the file is '$state', not complete"
       fi ;;
    1) [ ! -e "$work/$name.h5" ] || fail "$name: exit 1 but a result file was written" ;;
    2) if [ ! -f "$work/$name.h5" ]; then fail "$name: exit 2 but no result file kept"
       else state=$(result_status "$work/$name.h5")
            [ "${state%%$'\n'*}" = incomplete ] || fail "$name: exit 2 but the file is '$state', not incomplete"
       fi ;;
    3) ;;
    *) fail "$name: exit status $got is none of 0, 1, 2, 3" ;;
  esac
  if ls "$work/$name".h5.*tmp >/dev/null 2>&1; then
    fail "$name: temporary file left: $(ls "$work/$name".h5.*tmp)"
  fi
}

run_case() {
  local name=$1 want=$2; shift 2
  checks=$((checks + 1))
  # shellcheck disable=SC2086
  (cd "$work" && "$slidesim" -q $extra_args "$name.nml" >"$name.out" 2>"$name.err")
  local got=$? before=$failures
  [ "$got" = "$want" ] || fail "$name: exit status $got, expected $want"
  for needle in "$@"; do
    grep -qF -- "$needle" "$work/$name.err" || fail "$name: message lacks '$needle'"
  done
  check_files "$name" "$got"
  [ "$failures" = "$before" ] || echo "  message: $(head -c 600 "$work/$name.err")"
}

finish() {
  echo "$checks cases, $failures failed checks"
  [ "$failures" = 0 ]
}
