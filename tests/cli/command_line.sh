#!/usr/bin/env bash
# The command itself: --help lists the scenarios, --version prints a version, the
# built-in default runs and writes a complete result file with the input stored.
set -u
slidesim=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0; checks=0
check() { checks=$((checks + 1)); if ! eval "$1"; then echo "FAIL $2"; failures=$((failures + 1)); fi; }

check '"$slidesim" --help | grep -q point_mass' "--help lists point_mass"
check '"$slidesim" --version | grep -Eq "^slidesim [0-9]+\.[0-9]+\.[0-9]+"' "--version"
check '! "$slidesim" --no-such-option 2>/dev/null' "unknown option fails"
(cd "$work" && "$slidesim" -q > default.out 2> default.err); got=$?
check '[ $got = 0 ]' "default run exit status ($got): $(cat "$work/default.err")"
check 'grep -q "results" "$work/default.out"' "default run prints a summary"
check '[ -f "$work/slidesim_default.h5" ]' "default run writes slidesim_default.h5"
check 'h5dump -a /status "$work/slidesim_default.h5" | grep -q "\"complete\""' "default result marked complete"
check 'h5dump -d /input/namelist "$work/slidesim_default.h5" | grep -q point_mass' "input text stored"
check 'h5dump -a /point_mass/position/units "$work/slidesim_default.h5" | grep -q "\"m\""' "units attribute"
# The printed default input is a valid input file that gives the same run.
"$slidesim" --default-input > "$work/template.nml"
(cd "$work" && "$slidesim" -q -o again.h5 template.nml > again.out 2>&1); got=$?
check '[ $got = 0 ] && [ -f "$work/again.h5" ]' "--default-input output runs"

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
