#!/usr/bin/env bash
# The examples of README.md work and write nothing into the source tree: the
# slidesim command lines (indented lines starting with build/slidesim, and
# the sweep loop) run from the source folder with build/slidesim this
# build's program and /tmp this test's folder, exit 0 and leave no result,
# picture or input file in the tree; then each ```python block runs on the
# default run they wrote and must exit 0.
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
touch "$work/started"
sleep 1   # file times have a resolution of 1 s on some file systems
awk '/^    build\/slidesim / || /^    for .*; do$/ || /^      build\/slidesim / || /^    done$/ {print substr($0, 5)}' \
  "$root/README.md" | sed -e "s|build/slidesim|\"\$slidesim\"|g" -e "s|/tmp/|$work/|g" >"$work/commands.sh"
commands=$(grep -c slidesim "$work/commands.sh")
[ "$commands" -ge 5 ] || { echo "FAIL only $commands slidesim command lines found in README.md"; failures=$((failures + 1)); }
if ! (cd "$root" && slidesim=$slidesim bash -e "$work/commands.sh" >"$work/commands.out" 2>&1); then
  echo "FAIL README command lines:"; cat "$work/commands.sh" "$work/commands.out"; failures=$((failures + 1))
fi
for file in slidesim_default.h5 ellipsoid.h5 my_run.nml water_0.006.h5; do
  [ -s "$work/$file" ] || { echo "FAIL README command lines wrote no $file"; failures=$((failures + 1)); }
done
left=$(find "$root" -path "$root/build*" -prune -o -path "$root/.git" -prune -o -type f -newer "$work/started" \
         \( -name '*.h5' -o -name '*.xmf' -o -name '*.json' -o -name '*.png' -o -name '*.nml' -o -name '*.tmp' \) -print)
[ -z "$left" ] || { echo "FAIL README examples wrote into the source tree: $left"; failures=$((failures + 1)); }
awk -v dir="$work" '/^```python/ {n++; out = dir "/example" n ".py"; next} /^```/ {out = ""; next} out {print > out}' \
  "$root/README.md"
count=0
for example in "$work"/example*.py; do
  [ -f "$example" ] || continue
  count=$((count + 1))
  sed -i "s|/tmp/slidesim_default.h5|$work/slidesim_default.h5|g" "$example"
  if ! (cd "$root" && "$python" "$example" >"$example.out" 2>&1); then
    echo "FAIL README example $count:"; cat "$example.out"; failures=$((failures + 1))
  fi
done
[ "$count" -ge 2 ] || { echo "FAIL only $count python examples found in README.md"; failures=$((failures + 1)); }
echo "$commands command lines and $count python examples of README.md, $failures failed"
[ "$failures" = 0 ]
