# Sourced by the tests that check the results of every input (not a test
# itself): sets $results to the folder of tests/cli/support/every_input.sh's
# runs, the fixture's (SLIDESIM_EVERY_INPUT, set by ctest) or, started by
# hand, $work/every run now. Needs $slidesim, $root, $work and $failures.
results=${SLIDESIM_EVERY_INPUT:-}
if [ -z "$results" ]; then
  results=$work/every
  bash "$root/tests/cli/support/every_input.sh" "$slidesim" "$results" >/dev/null \
    || { echo "FAIL running every input (see $results)"; failures=$((failures + 1)); }
fi
