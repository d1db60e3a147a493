#!/usr/bin/env bash
# Towers from scripts/make_contact_inputs.py --tower (issue 27, point 8): the
# generator writes only towers that run (1 to 12 bowls, 10 s: measured, docs/
# contact.md); a taller tower (21 bowls ended singular at 8.18 s) or a longer
# run is refused with the limit and the way past it (--untested), which writes
# it with a warning. Cheap: the inputs are only checked (slidesim --check), not
# run. Before: every tower was written, silently.
set -u
slidesim=$1
root=$(pwd)
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"
make=("$root/scripts/make_contact_inputs.py")

generate() {   # generate NAME WANT [ARGS...]: runs the generator into $work/NAME, checks its exit status
  local name=$1 want=$2; shift 2
  checks=$((checks + 1))
  python3 "${make[@]}" --folder "$work/$name" "$@" > "$work/$name.out" 2> "$work/$name.err"
  local got=$?
  [ "$got" = "$want" ] || fail "$name: exit $got, expected $want: $(cat "$work/$name.err")"
}
has() {   # has NAME TEXT: standard error of NAME holds TEXT
  grep -qF -- "$2" "$work/$1.err" || fail "$1: standard error lacks '$2': $(cat "$work/$1.err")"
}

generate tall 2 --tower 13
has tall '--tower 13: 13 bowls, more than the 12 tested'
has tall 'conformal contact'
has tall 'add --untested'
[ ! -e "$work/tall" ] || fail "tall: a refused tower was written: $(ls -R "$work/tall")"
generate long 2 --tower 3 --duration 30
has long '--duration 30 s, longer than the 10 s tested'
generate never 2 --tower 3 --duration 0
has never '--duration 0.0: give the simulated time in s'
generate beyond 0 --tower 13 --untested
has beyond 'warning: untested tower: 13 bowls'
[ -f "$work/beyond/tower13.nml" ] || fail "beyond: --untested wrote no tower13.nml"

# the tallest tested tower: written without a word, 10 s, and slidesim accepts it
generate twelve 0 --tower 12
[ -s "$work/twelve.err" ] && fail "twelve: standard error not empty: $(cat "$work/twelve.err")"
grep -q 'duration = 10.0,' "$work/twelve/tower12.nml" || fail "twelve: not 10 s: $(grep duration "$work/twelve/tower12.nml")"
checks=$((checks + 1))
(cd "$work/twelve" && "$slidesim" -q --check tower12.nml > check.out 2>&1) || \
  fail "twelve: slidesim --check refused it: $(cat "$work/twelve/check.out")"

finish
