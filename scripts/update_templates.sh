#!/usr/bin/env bash
# Rewrites the shipped templates inputs/templates/<scenario>.nml with what
# `slidesim --default-input SCENARIO` prints: generated from the declarations
# of the input variables (src/io/io_declarations_*.f90) and the scenario's
# spec (inputs/templates/specs/<scenario>.spec). Run it after changing a
# declaration or a spec; the test cli_template_declarations fails until it is run.
#
#     scripts/update_templates.sh [SLIDESIM]     (default: build/slidesim)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
slidesim=${1:-$root/build/slidesim}
for spec in "$root"/inputs/templates/specs/*.spec; do
  scenario=$(basename "$spec" .spec)
  template=$root/inputs/templates/$scenario.nml
  "$slidesim" --default-input "$scenario" >"$template.new"
  mv "$template.new" "$template"
done
