#!/usr/bin/env bash
# A result path (-o PATH or &run output) that names a FIFO, a socket, or a
# link to one, or whose XDMF view (.xmf) does, is refused before any work
# (exit 3) and left as it was: slidesim renames its finished file onto the
# path, which would replace it (as root, -o /dev/full replaced the device).
# Only FIFOs and sockets made here are used: never a real device. Nothing
# may open them either: a writer would block on a FIFO without a reader,
# which `timeout` turns into a failure.
set -u
slidesim=$1
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

ellipsoid="$root/inputs/point_mass/ellipsoid.nml"
mkfifo "$work/fifo" "$work/view.xmf" || { echo "FAIL cannot make a FIFO"; exit 1; }
ln -s "$work/fifo" "$work/link.h5"

# refused NAME PATH_LEFT NEEDLE... -- ARGS...: exit 3 at once, the message has
# every needle, PATH_LEFT is still a FIFO (or socket), nothing else was made
refused() {
  local name=$1 left=$2; shift 2
  local needles=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do needles+=("$1"); shift; done
  shift
  checks=$((checks + 1))
  local before after
  before=$(ls -A "$work" | grep -v "^$name\.")
  (cd "$work" && timeout 120 "$slidesim" -q "$@" > "$name.out" 2> "$name.err" < /dev/null); local got=$?
  [ "$got" = 3 ] || fail "$name: exit status $got, expected 3: $(head -c 400 "$work/$name.err")"
  for needle in "${needles[@]}"; do
    grep -qF -- "$needle" "$work/$name.err" || fail "$name: message lacks '$needle': $(head -c 400 "$work/$name.err")"
  done
  [ -p "$work/$left" ] || [ -S "$work/$left" ] || fail "$name: $left is no longer a FIFO or socket"
  after=$(ls -A "$work" | grep -v "^$name\.")
  [ "$before" = "$after" ] || fail "$name: files changed: $(diff <(echo "$before") <(echo "$after") | tr '\n' ' ')"
}

refused fifo fifo '-o fifo: cannot write the result file: it is a FIFO (named pipe)' 'never replaces' \
  -- -o fifo "$ellipsoid"
refused link link.h5 '-o link.h5' 'it is a FIFO' -- -o link.h5 "$ellipsoid"
[ -L "$work/link.h5" ] || fail "link: link.h5 is no longer a link"
refused view view.xmf '"view.xmf", where its XDMF view goes, is a FIFO' -- -o view.h5 "$ellipsoid"
refused check fifo 'it is a FIFO' -- --check -o fifo "$ellipsoid"
sed "s|output = .*|output = 'fifo'|" "$ellipsoid" > "$work/from_input.nml"
refused from_input fifo "from_input.nml:5: &run: output = 'fifo': cannot write the result file: it is a FIFO" \
  -- from_input.nml
if [ -n "$h5python" ] && "$h5python" -c "import socket; s = socket.socket(socket.AF_UNIX); s.bind('$work/socket')" \
   2>/dev/null; then
  refused socket socket 'it is a socket' -- -o socket "$ellipsoid"
fi

# a regular file is still replaced, and a new name still written
echo old > "$work/old.h5"
checks=$((checks + 1))
(cd "$work" && "$slidesim" -q --set solver%duration=0.1 -o old.h5 "$ellipsoid" > old.out 2> old.err) || \
  fail "old: exit status $?: $(cat "$work/old.err")"
check_files old 0

finish
