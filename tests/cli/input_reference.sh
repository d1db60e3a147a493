#!/usr/bin/env bash
# The reference tables of docs/inputs.md are what `slidesim --input-reference`
# prints from the declarations of the input variables (issue 24): a
# declaration changed without the documentation fails here, with the command
# that rewrites the tables.
set -u
slidesim=$1
doc=docs/inputs.md   # tests run from the repository root
begin='<!-- BEGIN slidesim --input-reference -->'
end='<!-- END slidesim --input-reference -->'
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! grep -qxF -- "$begin" "$doc" || ! grep -qxF -- "$end" "$doc"; then
  echo "FAIL $doc lacks the markers '$begin' and '$end'"
  exit 1
fi
awk -v begin="$begin" -v end="$end" '$0 == end { inside = 0 } inside { print } $0 == begin { inside = 1 }' \
  "$doc" >"$work/committed.md"
"$slidesim" --input-reference >"$work/generated.md"; rc=$?
if [ $rc != 0 ]; then
  echo "FAIL slidesim --input-reference: exit status $rc"
  exit 1
fi
if ! diff -u "$work/committed.md" "$work/generated.md"; then
  echo "FAIL $doc differs from slidesim --input-reference (above: - committed, + generated);"
  echo "     regenerate it with: scripts/update_input_reference.sh build/slidesim"
  exit 1
fi
# the tables hold every declared group
for heading in '&run' '&solver' '&evaluation' '&channel' '&water' '&rider' '&sweep' \
               '&identify (scenario identify_rider)' '&identify (scenario identify_water)' '&optimize' '&surface' '&shape' '&grid' \
               '&point_mass' '&pendulum' '&fourbar' '&sled' '&contact_model' '&body' '&contact'; do
  if ! grep -qxF "### $heading" "$work/generated.md"; then
    echo "FAIL the reference lacks $heading"
    exit 1
  fi
done
echo "docs/inputs.md matches slidesim --input-reference"
