#!/usr/bin/env bash
# No output replaces a file the run reads, and every writer is checked
# (issue 27, points 3 and 4):
# - the result file, its XDMF view, --summary-json and a sweep's csv_output
#   may not be a file the run reads (the input, its geometry file, a
#   measurement CSV; also through a symbolic or a hard link) nor another
#   output: refused before any work (exit 1), the file unchanged, the
#   message naming the output and the file it would overwrite;
# - each writer refuses a device, a FIFO or a socket before any work
#   (exit 3, nothing written, the node left as it was): only nodes made here,
#   a private copy of /dev/full (mknod c 1 7), never a real device;
# - a CSV summary or summary JSON that cannot be written (a full disk: a
#   64 KiB tmpfs mounted in a mount namespace of our own) is exit 3 naming the
#   file, nothing of it left, and the printed summary does not name it.
set -u
slidesim=$(realpath "$1")
root=$(pwd)
. "$(dirname "$0")/support/cli_checks.sh"

cp -r "$root/inputs/demo_slide" "$root/inputs/design" "$root/inputs/sweep" "$work/"
cd "$work" || exit 1
short=(--set solver%duration=0.3)

# what a file is (type, device numbers, inode, size) and, a regular one, holds
state() {
  stat -c '%F %t %T %i %s' "$1"
  if [ -f "$1" ]; then sha256sum < "$1"; fi
}

# refused NAME WANT KEEP NEEDLE... -- ARGS...: exit WANT at once (ARGS run in
# $work), every NEEDLE on stderr, KEEP (a file or node) as it was, no result
# file NAME.h5 nor any other new file
refused() {
  local name=$1 want=$2 keep=$3; shift 3
  local needles=()
  while [ $# -gt 0 ] && [ "$1" != -- ]; do needles+=("$1"); shift; done
  shift
  checks=$((checks + 1))
  local before after kept
  kept=$(state "$keep")
  before=$(find . | sort)
  timeout 120 "$slidesim" -q "$@" > "$name.out" 2> "$name.err" < /dev/null; local got=$?
  [ "$got" = "$want" ] || fail "$name: exit status $got, expected $want: $(head -c 400 "$name.err")"
  for needle in "${needles[@]}"; do
    grep -qF -- "$needle" "$name.err" || fail "$name: message lacks '$needle': $(head -c 400 "$name.err")"
  done
  [ "$(state "$keep")" = "$kept" ] || \
    fail "$name: $keep was changed: $(stat -c '%F %s' "$keep")"
  after=$(find . | grep -v "^\./$name\.\(out\|err\)$" | sort)
  [ "$before" = "$after" ] || \
    fail "$name: files changed: $(diff <(echo "$before") <(echo "$after") | grep '^[<>]' | tr '\n' ' ')"
  # the inputs as shipped again, whatever the case did to them (main's build replaced them)
  for d in demo_slide design sweep; do cp -r "$root/inputs/$d/." "$work/$d/"; done
}

# ---- outputs that would overwrite a file the run reads (exit 1)
cd demo_slide || exit 1
refused geometry 1 slide.nml "point_mass.nml:17: &surface: geometry_file" \
  'input file "slide.nml" is the file the result file (-o slide.nml) would overwrite' -- \
  -o slide.nml point_mass.nml
ln -s slide.nml link.nml
refused symlink 1 slide.nml 'the result file (-o link.nml) would overwrite' -- -o link.nml point_mass.nml
ln slide.nml hard.nml
refused hardlink 1 slide.nml 'the result file (-o hard.nml) would overwrite (the same file, through a link)' -- \
  -o hard.nml point_mass.nml
refused json_geometry 1 slide.nml 'the summary JSON (--summary-json slide.nml) would overwrite' -- \
  --summary-json slide.nml -o r.h5 point_mass.nml
refused json_input 1 point_mass.nml '--summary-json point_mass.nml: the summary JSON would overwrite the input' \
  'file "point_mass.nml", which this run reads' -- --summary-json point_mass.nml -o r.h5 point_mass.nml
cp point_mass.nml view.xmf
refused xmf_input 1 view.xmf \
  '-o view.h5: the result file'"'"'s XDMF view "view.xmf" would overwrite the input file "view.xmf"' -- \
  -o view.h5 view.xmf
refused json_result 1 point_mass.nml \
  '--summary-json r.h5: the summary JSON would be written to the same file as the result file (-o r.h5)' -- \
  --summary-json r.h5 -o r.h5 point_mass.nml
refused json_view 1 point_mass.nml 'the same file as the result file'"'"'s XDMF view "r.xmf"' -- \
  --summary-json ./r.xmf -o r.h5 point_mass.nml
rm link.nml hard.nml view.xmf
cd ../design || exit 1
refused stations 1 rider_stations.csv 'CSV file' \
  '"rider_stations.csv" is the file the result file (-o rider_stations.csv) would overwrite' -- \
  -o rider_stations.csv identify_rider_demo.nml
cd ../sweep || exit 1
refused csv_geometry 1 ../demo_slide/slide.nml \
  "&sweep: csv_output = '../demo_slide/slide.nml': the CSV summary would overwrite the input file" -- \
  --set "sweep%csv_output='../demo_slide/slide.nml'" -o r.h5 demo_population.nml
refused csv_input 1 demo_population.nml 'the CSV summary would overwrite the input file "demo_population.nml"' -- \
  -o demo_population.h5 --set "sweep%csv_output='demo_population.nml'" demo_population.nml
cp ../demo_slide/slide.nml slide.csv   # a geometry file named like the default CSV summary
refused csv_default 1 slide.csv 'csv_output not given: "slide.csv", the result file'"'"'s name with .csv' \
  'the CSV summary would overwrite the input file "slide.csv"' -- \
  -o slide.h5 --set "surface%geometry_file='slide.csv'" demo_population.nml
rm slide.csv
cd .. || exit 1

# ---- every writer refuses a device, a FIFO or a socket before any work (exit 3)
mknod -m 666 full c 1 7 || { fail "cannot make a private device node"; finish; exit; }
mkfifo fifo
sockets=()
if [ -n "$h5python" ] && "$h5python" -c "import socket; s = socket.socket(socket.AF_UNIX); s.bind('socket')"; then
  sockets=(socket)
fi
for node in full fifo "${sockets[@]}"; do
  case $node in full) kind='a character device' ;; fifo) kind='a FIFO (named pipe)' ;; *) kind='a socket' ;; esac
  refused "result_$node" 3 "$node" "-o $node: cannot write the result file: it is $kind" -- \
    -o "$node" demo_slide/point_mass.nml
  refused "json_$node" 3 "$node" "--summary-json $node: cannot write the summary JSON: it is $kind" \
    'never replaces' -- --summary-json "$node" -o "json_$node.h5" demo_slide/point_mass.nml
  refused "csv_$node" 3 "$node" "&sweep: csv_output = '$node': cannot write the CSV summary: it is $kind" -- \
    "${short[@]}" --set "sweep%csv_output='$node'" -o "csv_$node.h5" sweep/demo_population.nml
done
ln -s full full_link.csv
refused csv_link 3 full "cannot write the CSV summary: it is a character device" -- \
  "${short[@]}" --set "sweep%csv_output='full_link.csv'" -o csv_link.h5 sweep/demo_population.nml
[ -L full_link.csv ] || fail "csv_link: the link was replaced"
rm -f fifo socket full_link.csv

# ---- a full disk: the CSV summary and the summary JSON (exit 3)
cat > full_disk.sh <<'SH'
set -u
slidesim=$1 dir=$2
mount -t tmpfs -o size=64k tmpfs "$dir" || exit 97
dd if=/dev/zero of="$dir/filler" bs=4k 2>/dev/null   # until the disk is full
"$slidesim" -q --set solver%duration=0.3 --set "sweep%csv_output='$dir/rides.csv'" -o disk_csv.h5 \
  sweep/demo_population.nml > disk_csv.out 2> disk_csv.err
echo "csv $?"
"$slidesim" -q --summary-json "$dir/summary.json" -o disk_json.h5 demo_slide/point_mass.nml \
  > disk_json.out 2> disk_json.err
echo "json $?"
ls -A "$dir" | tr '\n' ' ' > disk.left
SH
mkdir small
if unshare -m true 2>/dev/null; then
  result=$(unshare -m bash full_disk.sh "$slidesim" "$work/small")
  if grep -q . <<< "$result"; then
    checks=$((checks + 1))
    [ "$result" = $'csv 3\njson 3' ] || fail "full disk: exit statuses $(tr '\n' ' ' <<< "$result"), expected csv 3, json 3"
    grep -qF "cannot write the CSV summary \"$work/small/rides.csv\": No space left on device; nothing of it is kept" \
      disk_csv.err || fail "full disk csv: message: $(cat disk_csv.err)"
    grep -qF '(the result file "disk_csv.h5" is complete)' disk_csv.err || fail "full disk csv: message: $(cat disk_csv.err)"
    grep -q "CSV summary  *none: \"$work/small/rides.csv\" could not be written" disk_csv.out || \
      fail "full disk csv: the printed summary names the CSV: $(tail -n 3 disk_csv.out)"
    grep -qF "cannot write the summary JSON \"$work/small/summary.json\": No space left on device" disk_json.err || \
      fail "full disk json: message: $(cat disk_json.err)"
    [ "$(cat disk.left)" = 'filler ' ] || fail "full disk: files left on the disk: $(cat disk.left)"
  else
    echo "note: no tmpfs could be mounted here, the full-disk case is not testable"
  fi
else
  echo "note: no mount namespace here (unshare -m), the full-disk case is not testable"
fi

# ---- and a run whose outputs are all regular, new files still writes them all
checks=$((checks + 1))
"$slidesim" -q "${short[@]}" --summary-json sweep.json -o sweep.h5 sweep/demo_population.nml > ok.out 2> ok.err || \
  fail "regular outputs: exit status $?: $(cat ok.err)"
for f in sweep.h5 sweep.xmf sweep.csv sweep.json; do [ -s "$f" ] || fail "regular outputs: $f not written"; done
ls ./*.tmp sweep/*.tmp demo_slide/*.tmp 2>/dev/null && fail "temporary files left"

finish
