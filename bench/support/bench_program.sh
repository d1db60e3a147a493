# Sourced by the bench/*.sh scripts: bench_program BUILD NAME prints the path
# of benchmark NAME in build folder BUILD, or says how to build it and exits.
# A Release build makes the benchmarks on demand only (bench/CMakeLists.txt).
bench_program() {
  local program="$1/bench/$2"
  if [ ! -x "$program" ]; then
    echo "$program is not built: a Release build makes the benchmarks on demand" \
      "(cmake --build $1 --target benchmarks, or bench/run.sh)" >&2
    exit 1
  fi
  echo "$program"
}
