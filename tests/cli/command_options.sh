#!/usr/bin/env bash
# The command line (issue 13, item 4): --opt=value as well as --opt value, -
# and /dev/stdin for standard input, --set group%variable=value (repeatable,
# errors name an unknown group or variable), --check, --default-input
# SCENARIO for every scenario (each template runs), --summary-json FILE.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

ellipsoid="$root/inputs/point_mass/ellipsoid.nml"
# cmd NAME WANT NEEDLE... -- ARGS...: runs slidesim ARGS in $work, checks the
# exit status and that every needle is on stdout or stderr
cmd() {
  local name=$1 want=$2; shift 2
  local needles=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do needles+=("$1"); shift; done
  shift
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" "$@" > "$name.out" 2> "$name.err" < /dev/null); local got=$?
  [ "$got" = "$want" ] || fail "$name: exit status $got, expected $want: $(head -c 400 "$work/$name.err")"
  for needle in "${needles[@]}"; do
    grep -qF -- "$needle" "$work/$name.out" "$work/$name.err" || fail "$name: output lacks '$needle'"
  done
}

# --opt=value and --opt value
cmd output_eq 0 -- -q --output=eq.h5 "$ellipsoid"
check_files eq 0
cmd output_sep 0 -- -q --output sep.h5 "$ellipsoid"
check_files sep 0
cmd output_short 0 -- -q -o short.h5 "$ellipsoid"
check_files short 0
cmd no_value 1 'option --output needs a value' -- "$ellipsoid" --output
cmd empty_value 1 '--output needs a file name' -- --output= "$ellipsoid"
cmd flag_value 1 'option --check takes no value' -- --check=yes "$ellipsoid"
cmd unknown 1 'unknown option "--no-such"' -- --no-such "$ellipsoid"
cmd two_inputs 1 'only one input file' -- "$ellipsoid" "$ellipsoid"

# standard input: '-' and /dev/stdin, and a file named like an option after --
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q -o stdin.h5 - < "$ellipsoid" > stdin.out 2> stdin.err) || fail "stdin: $(cat "$work/stdin.err")"
check_files stdin 0
h5dump -d /input/source "$work/stdin.h5" 2>/dev/null | grep -q '<stdin>' || fail "stdin: /input/source does not say <stdin>"
checks=$((checks + 1))
(cd "$work" && cat "$ellipsoid" | "$slidesim" -q -o devstdin.h5 /dev/stdin > devstdin.out 2> devstdin.err) || \
  fail "/dev/stdin through a pipe: $(cat "$work/devstdin.err")"
check_files devstdin 0
grep -q 'Illegal seek\|Backtrace' "$work/devstdin.err" && fail "/dev/stdin: $(cat "$work/devstdin.err")"
printf "&run output = 'stdin_bad.h5' /\n&point_mass mass = -1 /\n" > "$work/bad_stdin.txt"
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q - < bad_stdin.txt > stdin_bad.out 2> stdin_bad.err); got=$?
[ $got = 1 ] || fail "stdin bad input: exit $got"
grep -q '<stdin>:2: &point_mass: mass = -1 is not allowed' "$work/stdin_bad.err" || fail "stdin bad input: $(cat "$work/stdin_bad.err")"
cp "$ellipsoid" "$work/-dash.nml"
cmd dash_file 0 -- -q -o dash.h5 -- -dash.nml
check_files dash 0

# --set: replace, add, several; errors name the group or the variable
cmd set_replace 0 -- -q -o set.h5 --set solver%duration=0.5 --set=point_mass%mass=3.0 "$ellipsoid"
check_files set 0
h5dump -d /point_mass/time "$work/set.h5" 2>/dev/null | grep -q '0.5' || fail "set_replace: duration not replaced"
h5dump -d /input/namelist "$work/set.h5" 2>/dev/null | grep -q -- '--set solver%duration=0.5' || \
  fail "set_replace: the override is not kept with the input text"
cmd set_add_group 0 -- -q -o set2.h5 --set "run%title='from the command line'" --set solver%output_step=0.05 "$ellipsoid"
h5dump -a /title "$work/set2.h5" 2>/dev/null | grep -q 'from the command line' || fail "set_add_group: title not set"
cmd set_list 0 'input ok' -- --check --set 'water%stations=5,10,20' --set 'water%stations(2)=12'
cmd set_unknown_group 1 '--set sover%rtol=1e-8' 'unknown namelist group &sover' '&solver' -- --check --set sover%rtol=1e-8 "$ellipsoid"
cmd set_unknown_var 1 '--set solver%rtl=1e-8' '&solver' 'unknown variable "rtl"' 'rtol' -- --check --set solver%rtl=1e-8 "$ellipsoid"
cmd set_bad_value 1 '--set solver%rtol=abc' 'rtol = abc is not allowed' -- --check --set solver%rtol=abc "$ellipsoid"
cmd set_no_percent 1 'write --set group%variable=value' -- --check --set rtol=1e-8 "$ellipsoid"
cmd set_two_values 1 'a single value is expected' -- --check --set 'solver%rtol=1e-8, 1e-9' "$ellipsoid"

# --check: builds the models, writes nothing
cmd check_ok 0 'ellipsoid.nml: input ok (scenario point_mass' -- --check -o checked.h5 "$ellipsoid"
[ ! -e "$work/checked.h5" ] && ! ls "$work"/checked.h5.*tmp >/dev/null 2>&1 || fail "check_ok: a file was written"
printf "&run output = 'check_bad.h5' /\n&surface kind = 'ellipsoid' /\n&point_mass v0 = 2.0 /\n" > "$work/check_bad.nml"
cmd check_bad 1 'check_bad.nml:3: &point_mass' 'parameter domain' -- --check check_bad.nml
[ ! -e "$work/check_bad.h5" ] || fail "check_bad: a file was written"

# --default-input SCENARIO: every template is a complete input that runs
# (the scenarios as --help lists them, so a new scenario needs its template)
scenarios=$("$slidesim" --help | awk '/^scenarios:/ {on = 1; next} on && NF == 0 {exit} on {print $1}')
[ -n "$scenarios" ] || fail "--help lists no scenarios"
for scenario in $scenarios; do
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" --default-input "$scenario" > "template_$scenario.nml") || fail "template $scenario not printed"
  grep -q "scenario = '$scenario'" "$work/template_$scenario.nml" || fail "template $scenario names another scenario"
  grep -q '^!' "$work/template_$scenario.nml" || fail "template $scenario has no comments"
  sed -i "s|^  output = .*|  output = 'template_$scenario.h5'|" "$work/template_$scenario.nml"
  run_case "template_$scenario" 0
done
cmd template_eq 0 "scenario = 'sled'" -- --default-input=sled
cmd template_unknown 1 'no such scenario' 'point_mass' -- --default-input torus
cmd template_default 0 "scenario = 'ride'" -- --default-input

# --summary-json FILE (both forms): the summary's numbers as JSON
cmd json_sep 0 -- -q -o json.h5 --summary-json summary.json "$ellipsoid"
cmd json_eq 0 -- -q -o json2.h5 --summary-json=summary2.json "$ellipsoid"
for f in summary.json summary2.json; do
  checks=$((checks + 1))
  python3 -c "import json, sys; json.load(open(sys.argv[1]))" "$work/$f" 2>/dev/null || fail "$f is not JSON"
done
cmd json_no_value 1 'option --summary-json needs a value' -- "$ellipsoid" --summary-json

finish
