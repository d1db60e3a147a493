#!/usr/bin/env bash
# Runs every input in inputs/ (and the built-in default) once into FOLDER, for
# the tests that check result files (result_conventions, xdmf_files,
# summary_json, plot_scripts): ctest runs this as the fixture
# cli_every_input (tests/CMakeLists.txt) and hands FOLDER to them in
# SLIDESIM_EVERY_INPUT; run by hand, each of them calls it itself.
#
#   every_input.sh SLIDESIM FOLDER
#
# Per input NAME (its path below inputs/ with / as _, without .nml; the
# default is "default"): NAME.h5 and NAME.xmf (the result), NAME.json
# (--summary-json), NAME.out, NAME.err, NAME.rc (exit status), and the list
# of NAMEs in FOLDER/names. Also "stopped": a run that fails part way (the
# mass leaves the ellipsoid over its pole, exit status 2), whose files must
# keep the same conventions. And "bouncing": a ball dropped on a floor that
# bounces six times and comes to rest (a flight with impacts: the XDMF file's
# phases and impacts, /contact/impacts). Exit status 1 if any run that should
# work did not.
set -u
slidesim=$1
folder=$2
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
rm -rf "$folder"
mkdir -p "$folder"
failures=0
run() {   # NAME [INPUT]
  local name=$1
  shift
  (cd "$root" && "$slidesim" -q -o "$folder/$name.h5" --summary-json "$folder/$name.json" "$@" \
     >"$folder/$name.out" 2>"$folder/$name.err")
  echo $? >"$folder/$name.rc"
  echo "$name" >>"$folder/names"
}
run default
for input in "$root"/inputs/*.nml "$root"/inputs/*/*.nml; do
  case $input in */demo_slide/slide.nml) continue ;; esac   # a geometry file other inputs name, not a run
  name=$(echo "${input#"$root"/inputs/}" | tr '/' '_' | sed 's/\.nml$//')
  # shorter runs of the same groups where a full one takes seconds (the
  # layout does not depend on the length; the physics has its own tests):
  # keeps this fixture near 10 s of CPU in Debug
  case $name in
    contact_egg) run "$name" --set solver%duration=3 "$input" ;;        # of 10 s
    templates_contact) run "$name" --set solver%duration=1 "$input" ;;  # the egg again
    contact_paraboloids) run "$name" --set solver%duration=2 "$input" ;;   # of 20 s
    contact_tower5) run "$name" --set solver%duration=0.5 "$input" ;;   # of the 5 s of the five-body tower input
    ride_demo_slide | templates_ride | parts_drop | parts_halfpipe | parts_bowl | parts_funnel | parts_patch | parts_bowl_table \
      | parts_bowl_halfpipe_mat | parts_bowl_halfpipe_ring)   # the default is this ride in full; the parts: test_slide_parts, test_slide_funnel, test_slide_patch, test_slide_bowl_table, bowl_halfpipe
      run "$name" --set solver%rtol=1e-6 --set solver%atol=1e-5 "$input" ;;
    # loose tolerances end before the lever-arm limit holds (exit 2): without the
    # constraint the end is checked and complete (tests/cli/optimize_verdicts.sh gates)
    templates_optimize) run "$name" --set optimize%ftol=0.1 --set optimize%xtol=0.1 \
      --set "optimize%constraint='none'" "$input" ;;
    # the robust optimisation (50 rides x 3 starts, a minute in Release): 10 rides, 1 start, loose
    design_optimize_robust) run "$name" --set "sweep%heading0_deg=0" --set optimize%starts=1 --unset optimize%seed \
      --set optimize%ftol=0.1 --set optimize%xtol=0.1 --set "optimize%constraint='none'" "$input" ;;
    *) run "$name" "$input" ;;
  esac
done
for name in $(cat "$folder/names"); do
  [ "$(cat "$folder/$name.rc")" = 0 ] \
    || { echo "FAIL $name: exit status $(cat "$folder/$name.rc"): $(cat "$folder/$name.err")"; failures=$((failures + 1)); }
done
printf "&run output = 'stopped.h5' /\n&solver duration = 5 /\n&surface kind = 'ellipsoid', a = 1, b = 1, c = 1 /\n&point_mass v0 = 1.2, dv0 = 2.0, gravity = 0, 0, 0 /\n" \
  >"$folder/stopped.nml"
(cd "$folder" && "$slidesim" -q -o "$folder/stopped.h5" --summary-json "$folder/stopped.json" stopped.nml >stopped.out 2>stopped.err)
echo $? >"$folder/stopped.rc"
[ "$(cat "$folder/stopped.rc")" = 2 ] || { echo "FAIL stopped run: exit status $(cat "$folder/stopped.rc"), expected 2"; failures=$((failures + 1)); }
cat >"$folder/bouncing.nml" <<'NML'
&run scenario = 'contact', output = 'bouncing.h5' /
&solver duration = 2, output_step = 0.01, rtol = 1e-10, atol = 1e-10 /
&shape name = 'floor', kind = 'plane' /
&shape name = 'ball', kind = 'sphere', radius = 0.1 /
&body name = 'ball', mass = 1, solid_of = 'ball', position = 0, 0, 1.1, velocity = 0.5, 0, 0 /
&contact name = 'on_floor', shape_1 = 'floor', body_2 = 'ball', shape_2 = 'ball', start = 'open',
  restitution = 0.5, close_speed = 0.1 /
NML
(cd "$folder" && "$slidesim" -q -o "$folder/bouncing.h5" --summary-json "$folder/bouncing.json" bouncing.nml >bouncing.out 2>bouncing.err)
echo $? >"$folder/bouncing.rc"
[ "$(cat "$folder/bouncing.rc")" = 0 ] || { echo "FAIL bouncing run: exit status $(cat "$folder/bouncing.rc"): $(cat "$folder/bouncing.err")"; failures=$((failures + 1)); }
echo "$(wc -l <"$folder/names") inputs run into $folder, $failures failures"
[ "$failures" = 0 ]
