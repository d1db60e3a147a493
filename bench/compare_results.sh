#!/usr/bin/env bash
# Runs shipped inputs with two builds and compares their result files bit for
# bit (h5diff): a refactor must leave every result as it was. Only provenance
# may differ: the attributes git_commit, created_utc, compiler and
# compiler_options and the cpu_time datasets; in a sweep also the wall_time
# datasets and the dimension scales' REFERENCE_LIST (its threads attach them
# in any order: two runs of one build differ there). An object or attribute
# in one file only is a difference too.
#
#     bench/compare_results.sh BASE_BUILD NEW_BUILD [INPUT.nml ...]
#
# BASE_BUILD and NEW_BUILD are build folders holding slidesim (Release builds
# of the two commits, e.g. a worktree of the base commit built into its own
# folder). Without inputs: the default run (`default`) and every shipped
# input, inputs/*/*.nml (each runs in seconds to a minute). An input is run
# from the repository root, as the documentation does. Exit 0 when every
# pair is the same (and both builds gave the same exit status), 1 otherwise.
set -u
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ $# -lt 2 ]; then
  echo "usage: $0 BASE_BUILD NEW_BUILD [INPUT.nml ...]" >&2
  exit 1
fi
base=$(cd "$1" && pwd)/slidesim
new=$(cd "$2" && pwd)/slidesim
shift 2
for exe in "$base" "$new"; do
  [ -x "$exe" ] || { echo "compare_results: $exe is not an executable" >&2; exit 1; }
done
if [ $# -gt 0 ]; then
  inputs=("$@")
else
  # every shipped input: each runs in under a minute (the longest, the
  # drop slide's ride, ~30 s); inputs/templates too, the defaults of each
  # scenario. Listed from the repository root, whatever the caller's folder.
  mapfile -t inputs < <(cd "$root" && ls inputs/*/*.nml)
  inputs=(default "${inputs[@]}")
fi
# Every object of a result file (path and kind) and every attribute (object@name).
object_names() {
  h5ls -r -v "$1" | awk '/^\// { object = $1; print object, $2; next }
                         /^    Attribute: / { print object "@" $2 }' | sort
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
for input in "${inputs[@]}"; do
  tag=$(echo "$input" | tr '/.' '__')
  args=()
  [ "$input" = default ] || args=("$input")
  (cd "$root" && timeout 1200 "$base" -o "$work/base_$tag.h5" "${args[@]}" >"$work/base_$tag.out" 2>&1)
  rc_base=$?
  (cd "$root" && timeout 1200 "$new" -o "$work/new_$tag.h5" "${args[@]}" >"$work/new_$tag.out" 2>&1)
  rc_new=$?
  if [ "$rc_base" != "$rc_new" ]; then
    echo "DIFFERENT $input: exit $rc_base (base) and $rc_new (new)"
    failed=1
    continue
  fi
  if [ ! -f "$work/base_$tag.h5" ] || [ ! -f "$work/new_$tag.h5" ]; then
    echo "DIFFERENT $input: no result file (exit $rc_base)"
    failed=1
    continue
  fi
  h5diff -r "$work/base_$tag.h5" "$work/new_$tag.h5" >"$work/diff_$tag.txt" 2>&1
  # h5diff -r names each object it compares ("attribute: <name of </path>> ...",
  # "dataset: </path> ..."), then "N differences found"; anything it cannot
  # compare or finds in one file only is a difference too
  unexpected=$(awk '
    /^(attribute|dataset|group|datatype): / { object = $0; next }
    /^[0-9]+ differences? found/ {
      if ($1 > 0 && object !~ /<(git_commit|created_utc|compiler|compiler_options|REFERENCE_LIST) of / &&
          object !~ /(cpu_time|wall_time)>/) print object
      next
    }
    /Not comparable|exist only|not found|Some objects are not comparable/ { print }
  ' "$work/diff_$tag.txt")
  # h5diff 1.10 passes over an object or attribute present in one file only
  # (it only sets its exit status, which provenance sets too): compare the
  # two files' lists of objects and attribute names as well
  one_sided=$(diff <(object_names "$work/base_$tag.h5") <(object_names "$work/new_$tag.h5") |
              sed -n 's/^< /only in base: /p; s/^> /only in new: /p')
  [ -z "$one_sided" ] || unexpected=$(printf '%s\n%s' "$unexpected" "$one_sided" | sed '/^$/d')
  if [ -n "$unexpected" ]; then
    echo "DIFFERENT $input (exit $rc_base):"
    echo "$unexpected" | sed 's/^/  /'
    failed=1
  else
    echo "same      $input (exit $rc_base)"
  fi
done
exit $failed
