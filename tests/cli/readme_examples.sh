#!/usr/bin/env bash
# The Python examples of README.md work on the default run: each ```python
# block is run (with its /tmp path pointed at this test's folder) and must
# exit 0.
set -u
slidesim=$1
root=$(pwd)
python=${SLIDESIM_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
"$slidesim" -q -o "$work/slidesim_default.h5" >/dev/null 2>&1 || { echo "FAIL the default run"; exit 1; }
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
echo "$count README examples, $failures failed"
[ "$failures" = 0 ]
