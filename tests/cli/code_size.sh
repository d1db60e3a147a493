#!/usr/bin/env bash
# No compiled function of the build above 1 MB of machine code. gfortran writes
# the finalizer and the deep copy of a derived type inline, component by
# component; a fixed-size array of a type with allocatable components inside
# another type made vehicle_flight_ode_t's finalizer 1.5 MB at -O3 (4.2 MB at
# -O0), 200 s of compile for each of three modules in a row and as much again
# in the program's link-time optimisation: CI's Release stage took 22.9 min
# with it, 10.5 min without (docs/DESIGN.md, "Derived types that compile
# fast"). The largest function
# after the fix is ~0.35 MB (a test routine at -O0).
set -u
build=$(cd "$(dirname "$1")" && pwd)
limit=1000000
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
find "$build" -name '*.o' -path '*CMakeFiles*' >"$work/objects"
count=$(wc -l <"$work/objects")
# the build's objects: the layers, FITPACK and the test programs (~600)
if [ "$count" -lt 300 ]; then
  echo "FAIL only $count object files under $build: not the build folder of slidesim"
  exit 1
fi
while read -r object; do
  readelf -sW "$object" | awk -v o="$object" '$4 == "FUNC" { print $3, $8, o }'
done <"$work/objects" >"$work/functions"
# readelf prints sizes above 99999 in hexadecimal: only those can pass the limit
failures=0
while read -r size name object; do
  if [ $((size)) -gt "$limit" ]; then
    echo "FAIL $name: $((size)) bytes of code ($object); limit $limit"
    failures=$((failures + 1))
  fi
done < <(grep '^0x' "$work/functions")
functions=$(wc -l <"$work/functions")
echo "$functions functions in $count objects, none above $limit bytes unless listed"
[ "$failures" -eq 0 ]
