#!/usr/bin/env bash
# The repetition check can fail (issue 24): on a copy of src/, scripts/ and
# docs/, classify_duplicates.py --check passes as on the tree, then the same
# 10-line block, added to two files whose pair is already classified (the
# two kind factories), makes it fail with that pair UNCLASSIFIED (the pair's
# content key changed). Exit 77 (skipped) without the `duplicates` command.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v duplicates > /dev/null || { echo "skipped: no duplicates command on this machine"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/scripts" "$work/docs"
cp -r "$root/src" "$work/src"
cp "$root/scripts/classify_duplicates.py" "$root/scripts/duplicates_classes.tsv" "$work/scripts/"
cp "$root/docs/duplicates.md" "$work/docs/"

python3 "$work/scripts/classify_duplicates.py" --check > "$work/before.txt" 2>&1
status=$?
if [ $status -ne 0 ]; then
  echo "FAIL: the copy's check exits $status before any change (want 0):"; cat "$work/before.txt"; exit 1
fi

block='
  pure real(wp) function added_twice(x, y) result(z)
    real(wp), intent(in) :: x(:), y(:)
    integer :: k
    z = 0
    do k = 1, size(x)
      if (x(k) > y(k)) z = z + (x(k) - y(k))**2
      if (x(k) < 0) z = z - x(k)*y(k)/(1 + abs(y(k)))
    end do
    z = sqrt(z)/max(1, size(x))
  end function added_twice'
for f in geometry/geometry_surface_factory.f90 kinetostatics/kinetostatics_force_law_factory.f90; do
  printf '%s\n' "$block" >> "$work/src/$f"
done
python3 "$work/scripts/classify_duplicates.py" --check > "$work/after.txt" 2>&1
status=$?
if [ $status -ne 1 ]; then
  echo "FAIL: the check exits $status after a block was added to two files (want 1):"; cat "$work/after.txt"; exit 1
fi
if ! grep -q 'UNCLASSIFIED geometry/geometry_surface_factory.f90:.* ~ kinetostatics/kinetostatics_force_law_factory.f90:' \
     "$work/after.txt"; then
  echo "FAIL: the check did not name the factories' pair UNCLASSIFIED:"; cat "$work/after.txt"; exit 1
fi
echo "ok: the check passes on the copy and fails, naming the pair, once a block is added to two files"
