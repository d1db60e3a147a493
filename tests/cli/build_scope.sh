#!/usr/bin/env bash
# scripts/run.sh builds the slidesim program alone, quickly; scripts/check.sh
# everything; either may come first in one build folder. Checked:
# - scripts/build.sh's choice (cmake replaced by a stub that logs its
#   arguments): with SLIDESIM_PROGRAM_ONLY a new folder is configured for the
#   program alone and a configured one kept as it is, only the slidesim target
#   built; without it a program-only folder is configured for everything
#   again, with a note; run.sh builds that way;
# - CMake's side (configure only): SLIDESIM_PROGRAM_ONLY compiles the layers'
#   link-time objects slim (no -ffat-lto-objects), has no test or benchmark
#   targets and refuses to install; configured for everything again, the fat
#   objects and the tests are back, and the benchmarks a target of their own,
#   with link-time optimisation outside `all` (built on demand).
set -u
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

mkdir "$work/bin"
cat >"$work/bin/cmake" <<'EOF'
#!/usr/bin/env bash
echo "$*" >>"$CMAKE_STUB_LOG"
EOF
chmod +x "$work/bin/cmake"
# build.sh with the stub: $1 the build folder, then environment assignments
stub_build() {
  local build=$1
  shift
  : >"$work/log"
  env PATH="$work/bin:$PATH" CMAKE_STUB_LOG="$work/log" SLIDESIM_BUILD_DIR="$build" "$@" \
    bash "$root/scripts/build.sh" >"$work/out" 2>"$work/err" || fail "build.sh ($*): exit status $?"
  configure=$(grep -- '^-S ' "$work/log")
  build_step=$(grep -- '^--build ' "$work/log")
}

stub_build "$work/fresh" SLIDESIM_PROGRAM_ONLY=1
case " $configure " in *" -DSLIDESIM_PROGRAM_ONLY=ON "*) ;; *) fail "program only, new folder: $configure" ;; esac
case "$build_step" in *"--target slidesim") ;; *) fail "program only builds: $build_step" ;; esac

mkdir "$work/full"
echo 'SLIDESIM_PROGRAM_ONLY:BOOL=OFF' >"$work/full/CMakeCache.txt"
stub_build "$work/full" SLIDESIM_PROGRAM_ONLY=1
case "$configure" in *SLIDESIM_PROGRAM_ONLY*) fail "program only, configured folder changed: $configure" ;; esac
case "$build_step" in *"--target slidesim") ;; *) fail "program only in a full folder builds: $build_step" ;; esac

mkdir "$work/program"
echo 'SLIDESIM_PROGRAM_ONLY:BOOL=ON' >"$work/program/CMakeCache.txt"
stub_build "$work/program"
case " $configure " in *" -DSLIDESIM_PROGRAM_ONLY=OFF "*) ;; *) fail "full build of a program-only folder: $configure" ;; esac
case "$build_step" in *--target*) fail "full build builds targets: $build_step" ;; esac
grep -q 'configuring it for everything' "$work/err" || fail "no note on the reconfiguration: $(cat "$work/err")"
stub_build "$work/program" SLIDESIM_BUILD_TYPE=Debug
case " $configure " in *" -DCMAKE_BUILD_TYPE=Debug -DSLIDESIM_PROGRAM_ONLY=OFF "*) ;;
  *) fail "Debug full build: $configure" ;; esac

grep -q '^SLIDESIM_PROGRAM_ONLY=1 "$root/scripts/build.sh"' "$root/scripts/run.sh" ||
  fail "run.sh does not build the program only"

# CMake's side: configure only (a build would take minutes)
cmake -S "$root" -B "$work/cmake" -DCMAKE_BUILD_TYPE=Release -DSLIDESIM_PROGRAM_ONLY=ON \
  >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configure SLIDESIM_PROGRAM_ONLY=ON"; }
flags=$work/cmake/src/CMakeFiles/slidesim_base.dir/flags.make
if grep -q 'link-time optimisation of the program and benchmarks: ON' "$work/configure.log"; then
  grep -q -- '-flto=auto' "$flags" || fail "program only: no -flto: $(grep FLAGS "$flags")"
  grep -q -- '-ffat-lto-objects' "$flags" && fail "program only: fat LTO objects: $(grep FLAGS "$flags")"
else
  echo "no link-time optimisation in this configuration: the objects not checked"
fi
cmake --build "$work/cmake" --target help >"$work/targets" 2>&1
grep -q '\.\.\. slidesim$' "$work/targets" || fail "program only: no slidesim target"
grep -qE '(test_|_bench|fitpack_test)' "$work/targets" && fail "program only: test or bench targets"
cmake --install "$work/cmake" --prefix "$work/prefix" >"$work/install.log" 2>&1 &&
  fail "program only: cmake --install went ahead"
grep -q 'SLIDESIM_PROGRAM_ONLY=OFF to install' "$work/install.log" ||
  fail "program only: install refused without the reason: $(tail -3 "$work/install.log")"
[ -e "$work/prefix" ] && fail "program only: the install wrote $work/prefix"

cmake -S "$root" -B "$work/cmake" -DSLIDESIM_PROGRAM_ONLY=OFF >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; fail "configure again with SLIDESIM_PROGRAM_ONLY=OFF"; }
if grep -q 'link-time optimisation of the program and benchmarks: ON' "$work/configure.log"; then
  grep -q -- '-flto=auto -ffat-lto-objects' "$flags" || fail "full build: not fat LTO objects: $(grep FLAGS "$flags")"
fi
cmake --build "$work/cmake" --target help >"$work/targets" 2>&1
grep -q '\.\.\. test_base$' "$work/targets" || fail "full build after program only: no tests"
# the benchmarks: a target of their own; with link-time optimisation on demand
# only (not in `all`: each is a whole-program optimisation no test needs)
grep -q '\.\.\. benchmarks$' "$work/targets" || fail "full build: no benchmarks target"
if grep -q 'link-time optimisation of the program and benchmarks: ON' "$work/configure.log"; then
  grep -qE '^bench/all: .*(_bench|contact_profile)' "$work/cmake/CMakeFiles/Makefile2" &&
    fail "full build with LTO: the benchmarks are in all"
fi

echo "build scope: $failures failures"
[ "$failures" = 0 ]
