#!/usr/bin/env bash
# Mutation test of the input boundary (issue 12): a few hundred seeded,
# deterministic mutants of the shipped inputs, each checked and a share run
# fully; see tests/cli/mutants.py for what every run must do. Then the group
# injection (issue 27): every group a scenario does not read, added to its
# inputs and geometry files, is refused by name and line
# (tests/cli/group_injection.py).
# SLIDESIM_MUTANTS sets the number of mutants (default 500).
set -u
slidesim=$1
root=$(pwd)
for python in python3 /usr/bin/python3; do
  if command -v "$python" >/dev/null && "$python" -c 'import h5py' 2>/dev/null; then
    "$python" "$(dirname "$0")/mutants.py" "$slidesim" "$root"; mutants=$?
    "$python" "$(dirname "$0")/group_injection.py" "$slidesim" "$root"; groups=$?
    [ "$mutants" = 0 ] && [ "$groups" = 0 ]
    exit
  fi
done
echo "FAIL no python3 with h5py (scripts/install-dependencies.sh installs python3-h5py)"
exit 1
