#!/usr/bin/env bash
# A slide from a manufacturer's element table (&slide_elements elements_file,
# src/io/io_element_table.f90): the demo slide's table
# (inputs/demo_slide/elements.csv, inputs/geometry/demo_slide_table.nml)
# builds the same slide as its namelist (inputs/demo_slide/slide.nml): the
# /geometry group of both results identical to the last bit (h5diff, no
# tolerance). A bad table is refused before any work (exit 1, nothing
# written) naming the file, the line, the column, the value and what is allowed.
set -u
slidesim=$1
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
"$slidesim" -q -o "$work/namelist.h5" "$root/inputs/demo_slide/slide.nml" >/dev/null 2>&1 || fail "slide.nml"
"$slidesim" -q -o "$work/table.h5" "$root/inputs/geometry/demo_slide_table.nml" >"$work/out" 2>&1 \
  || fail "demo_slide_table.nml: $(cat "$work/out")"
h5diff "$work/namelist.h5" "$work/table.h5" /geometry /geometry >"$work/diff" 2>&1 \
  || fail "the table's slide differs from the namelist's: $(head -5 "$work/diff")"
# bad tables: CASE, the table's lines after the header, what the message must hold
header='kind, length, radius, angle, slope, direction, turns, drop'
bad() {   # NAME TEXT EXPECTED [HEADER]
  local name=$1 text=$2 expected=$3
  mkdir -p "$work/$name"
  printf '%s\n%s\n' "${4:-$header}" "$text" >"$work/$name/table.csv"
  sed "s|elements_file = '../demo_slide/elements.csv'|elements_file = 'table.csv'|" \
    "$root/inputs/geometry/demo_slide_table.nml" >"$work/$name/input.nml"
  (cd "$work/$name" && "$slidesim" -q -o out.h5 input.nml >out 2>&1)
  local rc=$?
  [ "$rc" = 1 ] || fail "$name: exit status $rc, not 1"
  grep -qF -- "$expected" "$work/$name/out" || fail "$name: no '$expected' in: $(cat "$work/$name/out")"
  [ -e "$work/$name/out.h5" ] && fail "$name: a result was written"
}
bad kind 'straight, 6.0,,,12.0
slope, 3.0' "table.csv:3: column 1 (kind): 'slope': element 2: the kind must be straight, curve, helix, runout, drop, bowl or funnel"
bad number 'straight, six' "table.csv:2: column 2 (length): 'six': element 1: not a number"
bad range 'straight, 6.0,,,90' "table.csv:2: column 5 (slope): '90': element 1: must be in [-45.0, 85.0] deg"
bad steep 'straight, 6.0,,,50' "table.csv:2: column 5 (slope): '50.0': element 1: a straight's slope must lie in [-45, 45] (deg; only a drop is steeper)"
bad drop_slope 'drop,, 8.0,,30,,,10' "table.csv:2: column 5 (slope): '30.0': element 1: a drop falls at a top slope in [45.0, 85.0] (deg)"
bad drop_second 'straight, 6.0,,,12.0
drop,, 8.0,,80,,,10
straight, 6.0,,,3.0' "slide element 2 (drop): a drop is the trap-door start of a slide: only the first element can be a drop"
bad unused 'curve, 3.0, 5.0, 90' "table.csv:2: column 2 (length): '3.0': element 1: a curve does not use length; give 0 or leave it out"
bad needed 'helix,, 4.0,,,,,1.0' "table.csv:2: column 7 (turns): '0.0': element 1: a helix needs turns > 0"
bad column 'straight, 6.0' "table.csv:1: column 2: 'len': the header needs a column name: kind, length" 'kind, len'
bad cells 'straight, 6.0, 1, 2' "element 1: has 4 cells, the header 2" 'kind, length'
bad empty '' "the element table has no element"
printf 'straight, 6.0\n' >"$work/both.csv"
sed -e "s|elements_file = '../demo_slide/elements.csv'|elements_file = '$work/both.csv', kind = 'straight'|" \
  "$root/inputs/geometry/demo_slide_table.nml" >"$work/both.nml"
"$slidesim" -q -o "$work/both.h5" "$work/both.nml" >"$work/out" 2>&1
[ $? = 1 ] && grep -q "the elements come from elements_file" "$work/out" || fail "kind beside elements_file: $(cat "$work/out")"
[ "$failures" = 0 ] && echo "element table checks passed"
[ "$failures" = 0 ]
