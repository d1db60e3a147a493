#!/usr/bin/env bash
# Rewrites the reference tables of docs/inputs.md (between the markers
# "<!-- BEGIN slidesim --input-reference -->" and "<!-- END ... -->") with
# what `slidesim --input-reference` prints: the declarations of every input
# variable (src/io/io_declarations_*.f90). Run it after changing a
# declaration; the test cli_input_reference fails until it is run.
#
#     scripts/update_input_reference.sh [SLIDESIM]     (default: build/slidesim)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
slidesim=${1:-$root/build/slidesim}
doc=$root/docs/inputs.md
begin='<!-- BEGIN slidesim --input-reference -->'
end='<!-- END slidesim --input-reference -->'
grep -qxF -- "$begin" "$doc" && grep -qxF -- "$end" "$doc" || { echo "$doc lacks the markers" >&2; exit 1; }
reference=$(mktemp)
trap 'rm -f "$reference" "$doc.new"' EXIT
"$slidesim" --input-reference >"$reference"
awk -v begin="$begin" -v end="$end" -v reference="$reference" '
  $0 == begin { print; while ((getline line < reference) > 0) print line; skipping = 1; next }
  $0 == end { skipping = 0 }
  !skipping { print }' "$doc" >"$doc.new"
mv "$doc.new" "$doc"
