#!/usr/bin/env bash
# --summary-json FILE: for one input of every scenario (the default is a ride) the JSON loads, has the
# keys of the printed summary with a unit for every number, and its numbers
# equal the HDF5 result's (tests/cli/check_summary_json.py); a JSON path that
# cannot be written is exit status 3.
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for input in builtin:default water/demo_slide.nml point_mass/ellipsoid.nml geometry/helix_tube.nml pendulum/double.nml \
             fourbar/crank_rocker.nml sled/demo_slide.nml; do
  name=$(basename "$input" .nml | tr ':' '_')
  case $input in builtin:*) path=$input ;; *) path=$root/inputs/$input ;; esac
  if ! (cd "$root" && "$slidesim" -q -o "$work/$name.h5" --summary-json "$work/$name.json" "$path" \
          >"$work/$name.out" 2>"$work/$name.err"); then
    echo "FAIL $input: exit status non-zero: $(cat "$work/$name.err")"; failures=$((failures + 1)); continue
  fi
  "$python" "$root/tests/cli/check_summary_json.py" "$work/$name.json" "$work/$name.h5" "$work/$name.out" \
    || failures=$((failures + 1))
done
"$slidesim" -q -o "$work/x.h5" --summary-json "$work/no/such/folder/s.json" >/dev/null 2>"$work/bad.err"
got=$?
[ $got = 3 ] || { echo "FAIL unwritable summary path: exit status $got, expected 3"; failures=$((failures + 1)); }
grep -q 'no/such/folder/s.json' "$work/bad.err" || { echo "FAIL unwritable summary path not named"; failures=$((failures + 1)); }
[ "$failures" = 0 ]
