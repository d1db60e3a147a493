#!/usr/bin/env bash
# The command itself: --help lists the scenarios, --version prints a version, the
# built-in default runs and writes a complete result file with the input stored.
slidesim=$1
. "$(dirname "$0")/support/checks.sh"

check '"$slidesim" --help | grep -q point_mass' "--help lists point_mass"
check '"$slidesim" --version | grep -Eq "^slidesim [0-9]+\.[0-9]+\.[0-9]+"' "--version"
check '"$slidesim" --version | grep -Eq "\(git ([0-9a-f]{40}(-dirty)?|unknown)\)$"' "--version names the build's commit"
check '! "$slidesim" --no-such-option 2>/dev/null' "unknown option fails"
(cd "$work" && "$slidesim" -q > default.out 2> default.err); got=$?
check '[ $got = 0 ]' "default run exit status ($got): $(cat "$work/default.err")"
check 'grep -q "results" "$work/default.out"' "default run prints a summary"
check '[ -f "$work/slidesim_default.h5" ]' "default run writes slidesim_default.h5"
check 'h5dump -a /status "$work/slidesim_default.h5" | grep -q "\"complete\""' "default result marked complete"
check 'h5dump -d /input/namelist "$work/slidesim_default.h5" | grep -q "scenario = .*ride"' "input text stored"
check 'h5dump -a /water/position/units "$work/slidesim_default.h5" | grep -q "\"m\""' "units attribute"
# The file names the commit the program was built from (--version's), not 'unknown'.
commit=$("$slidesim" --version | sed -n 's/.*(git \(.*\))$/\1/p')
check '[ -n "$commit" ] && h5dump -a /git_commit "$work/slidesim_default.h5" | grep -q "\"$commit\""' \
  "result's git_commit is the build's ($commit)"
# The printed default input is a valid input file that gives the same run.
"$slidesim" --default-input > "$work/template.nml"
(cd "$work" && "$slidesim" -q -o again.h5 template.nml > again.out 2>&1); got=$?
check '[ $got = 0 ] && [ -f "$work/again.h5" ]' "--default-input output runs"

# Paths inside an input are relative to that input's folder, and built-in inputs
# work from any folder: run the repository's demo-slide inputs from elsewhere.
repo=$PWD
(cd "$work" && "$slidesim" -q -o water.h5 "$repo/inputs/water/demo_slide.nml" > water.out 2>&1); got=$?
check '[ $got = 0 ]' "geometry_file relative to the input's folder ($(tail -2 "$work/water.out"))"
printf "&run output = 'slide.h5' /\n&solver duration = 1 /\n&surface kind = 'slide', geometry_file = 'builtin:demo_slide' /\n&point_mass u0 = 1.0, v0 = 1.5, du0 = 0.5 /\n" > "$work/builtin.nml"
(cd "$work" && "$slidesim" -q builtin.nml > builtin.out 2>&1); got=$?
check '[ $got = 0 ]' "builtin:demo_slide from another folder ($(tail -2 "$work/builtin.out"))"

echo "$((checks - failures)) passed, $failures failed"
[ $failures = 0 ]
