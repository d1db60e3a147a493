#!/usr/bin/env bash
# --set on a group the input gives more than once (&shape, &body, &contact)
# changes the occurrence it names, body(2)%... or body(name)%..., and is
# refused when it names none (never the first one silently); a refusal a
# --set caused says so; a word needs no quotes on the command line
# (--set solver%method=bdf), a text with / gets the quoting to use.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

paraboloids="$root/inputs/contact/paraboloids.nml"
egg="$root/inputs/contact/egg.nml"
# cmd NAME WANT NEEDLE... -- ARGS...: runs slidesim -q ARGS in $work, checks the
# exit status, every needle on stderr (a needle '!TEXT': TEXT absent) and that
# no file was written
cmd() {
  local name=$1 want=$2; shift 2
  local needles=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do needles+=("$1"); shift; done
  shift
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" -q "$@" > "$name.out" 2> "$name.err" < /dev/null); local got=$?
  [ "$got" = "$want" ] || fail "$name: exit status $got, expected $want: $(head -c 400 "$work/$name.err")"
  for needle in "${needles[@]}"; do
    if [ "${needle:0:1}" = '!' ]; then
      ! grep -qF -- "${needle:1}" "$work/$name.err" || fail "$name: message has '${needle:1}'"
    else
      grep -qF -- "$needle" "$work/$name.err" || fail "$name: message lacks '$needle': $(head -c 400 "$work/$name.err")"
    fi
  done
  if ls "$work"/*.h5 "$work"/*.tmp >/dev/null 2>&1; then fail "$name: a file was written"; rm -f "$work"/*.h5 "$work"/*.tmp; fi
}

# which body: refused without saying, the way to say it shown (quoted for the shell)
cmd which 1 '--set body%mass=3: the input has 2 &body groups' "body(1) name = 'paraboloid_2' at line" \
  '--set "body(2)%mass=3"' '--set "body(paraboloid_3)%mass=3"' -- --check --set body%mass=3 "$paraboloids"
cmd which_shape 1 "--set shape%name='x': the input has 3 &shape groups" -- --check --set "shape%name='x'" "$paraboloids"
# the value reaches the occurrence named (its reader refuses it, naming the --set)
cmd second 1 '--set body(2)%mass=-1: &body: mass = -1' -- --check --set 'body(2)%mass=-1' "$paraboloids"
cmd first 1 '--set body(1)%mass=-1: &body: mass = -1' -- --check --set 'body(1)%mass=-1' "$paraboloids"
cmd by_name 1 '--set body(paraboloid_3)%mass=-1: &body: mass = -1' -- \
  --check --set 'body(paraboloid_3)%mass=-1' "$paraboloids"
cmd by_quoted_name 1 "--set body('paraboloid_2')%mass=-1: &body: mass = -1" -- \
  --check --set "body('paraboloid_2')%mass=-1" "$paraboloids"
cmd second_ok 0 -- --check --set 'body(2)%mass=3' --set 'contact(p3_in_p2)%side_1=1' "$paraboloids"
cmd beyond 1 '--set body(3)%mass=3: k in body(k) must be 1 to 2' -- --check --set 'body(3)%mass=3' "$paraboloids"
cmd no_name 1 "--set body(egg)%mass=3: no &body group has name = 'egg'" "body(2) name = 'paraboloid_3'" -- \
  --check --set 'body(egg)%mass=3' "$paraboloids"
cmd single 0 -- --check --set 'body(1)%mass=0.1' "$egg"
# a refusal of the file's line that a --set caused says so
cmd renamed 1 "paraboloids.nml:" "(in the input as changed by --set shape(2)%name='x')" -- \
  --check --set "shape(2)%name='x'" "$paraboloids"

# text values: a word without quotes; a wrong one without the file's "(in quotes)"
cmd bdf 0 -- --check --set solver%method=bdf "$egg"
cmd bdf_quoted 0 -- --check --set "solver%method='bdf'" "$egg"
cmd bdff 1 '--set solver%method=bdff: &solver: method = bdff is not allowed: must be one of adams bdf' \
  '!in quotes' -- --check --set solver%method=bdff "$egg"
cmd slash 1 "--set run%output=out/x.h5: unexpected" "--set \"run%output='out/x.h5'\"" -- \
  --check --set run%output=out/x.h5 "$egg"

finish
