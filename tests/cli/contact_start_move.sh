#!/usr/bin/env bash
# A body whose start position does not touch is moved along the contact
# normal until it does (docs/contact.md, &body): every such move is said on
# standard error (which body, how far, along which contact's normal), and a
# move longer than the body's own size (a mistyped position: 5.0 for 0.05,
# a sign) is refused at the &body's position (exit 1, nothing written).
set -u
slidesim=$1
# shellcheck source=support/cli_checks.sh
source "$(dirname "$0")/support/cli_checks.sh"

ball() {   # ball NAME Z: a ball of radius 0.1 m at height Z over the table
  printf "&run scenario = 'contact', output = '%s.h5' /\n&solver duration = 0.01, output_step = 0.01 /\n&shape name = 'table', kind = 'plane' /\n&shape name = 'ball', kind = 'ellipsoid', a = 0.1, b = 0.1, c = 0.1 /\n&body name = 'ball', mass = 1, solid_of = 'ball',\n  position = 0, 0, %s, angles_deg = 90, 0, 0 /\n&contact name = 'c', body_1 = 'ground', shape_1 = 'table', body_2 = 'ball', shape_2 = 'ball' /\n" \
    "$1" "$2" > "$work/$1.nml"
}

# said, not quiet: lowered by 0.15 m, lifted by 0.05 m; nothing where it touches
said() {   # said NAME NEEDLE: a run without -q whose standard error has NEEDLE (or none if NEEDLE is empty)
  checks=$((checks + 1))
  (cd "$work" && "$slidesim" "$1.nml" >"$1.out" 2>"$1.err") || fail "$1: exit status $?: $(cat "$work/$1.err")"
  if [ -n "$2" ]; then
    grep -qF -- "$2" "$work/$1.err" || fail "$1: standard error lacks '$2': $(cat "$work/$1.err")"
  elif grep -q 'lowered\|lifted' "$work/$1.err"; then
    fail "$1: a move is reported where the ball touches: $(cat "$work/$1.err")"
  fi
}
ball above 0.25
said above "contact: body 'ball' lowered by 0.15 m along the normal of contact 'c' to touch shape 'table'"
ball sunk 0.05
said sunk "contact: body 'ball' lifted by 0.05 m along the normal of contact 'c'"
ball touching 0.1
said touching ''

# refused: further than the ball's size (its box's diagonal, 0.3464 m)
ball far 5.0
run_case far 1 'far.nml:6:' '&body: position = [0.0, 0.0, 5.0]' "body 'ball' would be lowered by 4.9 m" \
  "contact 'c'" 'more than its own size (0.34641 m)'
ball below -1
run_case below 1 'below.nml:6:' "body 'ball' would be lifted by 1.1 m" 'more than its own size'

finish
