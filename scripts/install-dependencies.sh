#!/usr/bin/env bash
# Installs what slidesim needs from Debian's packages (Debian 12), in sets:
#
#   install-dependencies.sh --runtime   what builds slidesim and draws its plots
#                                       (scripts/run.sh): the build set and the
#                                       plot set below, and CVODE
#   install-dependencies.sh [--test]    that and the test and viewer extras
#                                       (scripts/check.sh, the default)
#   install-dependencies.sh --build     the build set: compiler, CMake, LAPACK,
#                                       MINPACK, HDF5 (with its Fortran library),
#                                       and what builds CVODE from Debian's source
#                                       package (below); then CVODE
#   install-dependencies.sh --build-packages   the build set without CVODE
#   install-dependencies.sh --plot      the plot set: Python with numpy, h5py and
#                                       matplotlib (the plot scripts; the slidesim
#                                       program does not need them)
#   install-dependencies.sh --list build|plot|runtime|test   prints a set,
#                                       installs nothing (runtime: build and plot)
#
# scripts/run.sh installs the build set's packages, then the plot set's in the
# background while it builds CVODE and slidesim: apt's unpacking waits on the
# disk, the build on the processors (the plot set is 88 of the 230 packages of
# a bare system's first run, and most of its files). Never two apt-get at once:
# the CVODE build takes no dpkg lock (dpkg-source -x only unpacks files).
#
# The extras: scipy (Debian's scipy 1.10.1 regenerates the FITPACK tables),
# pint and udunits-bin (the tests parse the units in result files), xarray with
# h5netcdf (the tests open every result group with it), pandas and venv (the
# Python package's test), hdf5-tools (h5diff compares results), ParaView (the
# tests open every XDMF file with its XDMF reader) and Open MPI (sweeps across
# ranks: mpirun -n N slidesim sweep.nml; the build works without it).
# No Debian SUNDIALS: CVODE comes from the project's own build below, and
# Debian's libsundials-dev would bring PETSc, hypre, MUMPS and Trilinos.
# Idempotent: installs only what is missing.
set -euo pipefail

# python3-munkres: matplotlib's fonttools needs scipy or munkres; without it
# apt takes scipy (62 MB with pythran), which only the tests use
build_packages=(gfortran cmake make liblapack-dev libblas-dev minpack-dev libhdf5-dev
                curl ca-certificates xz-utils dpkg-dev)
plot_packages=(python3 python3-numpy python3-h5py python3-matplotlib python3-munkres)
runtime_packages=("${build_packages[@]}" "${plot_packages[@]}")
test_packages=(hdf5-tools libopenmpi-dev openmpi-bin python3-scipy python3-pint python3-xarray
               python3-h5netcdf python3-pandas python3-venv udunits-bin paraview python3-paraview
               ffmpeg)   # ffmpeg: viewer extra, the film of a ride (slidesim-plot --movie; a GIF without it)

usage="usage: $0 [--runtime | --test | --build | --build-packages | --plot | --list build|plot|runtime|test]"
cvode=yes
case ${1:---test} in
  --runtime) packages=("${runtime_packages[@]}") ;;
  --test) packages=("${runtime_packages[@]}" "${test_packages[@]}") ;;
  --build) packages=("${build_packages[@]}") ;;
  --build-packages) packages=("${build_packages[@]}"); cvode=no ;;
  --plot) packages=("${plot_packages[@]}"); cvode=no ;;
  --list)
    case ${2:-} in
      build) printf '%s\n' "${build_packages[@]}" ;;
      plot) printf '%s\n' "${plot_packages[@]}" ;;
      runtime) printf '%s\n' "${runtime_packages[@]}" ;;
      test) printf '%s\n' "${test_packages[@]}" ;;
      *) echo "$usage" >&2; exit 1 ;;
    esac
    exit 0 ;;
  *) echo "$usage" >&2; exit 1 ;;
esac
[ $# -le 1 ] || { echo "$usage" >&2; exit 1; }

sudo=""
if [ "$(id -u)" != 0 ]; then
  sudo=sudo
fi
need_root() {
  if [ -n "$sudo" ] && ! command -v sudo >/dev/null; then
    echo "error: need root or sudo to install: $1" >&2
    exit 1
  fi
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} > 0)); then
  need_root "${missing[*]}"
  echo "installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
[ "$cvode" = yes ] || exit 0

# CVODE with optimisation. Debian's libsundials 6.4.1+dfsg1-3 is compiled
# without any: its debian/rules passes -DCMAKE_C_FLAGS=-fcommon, which
# replaces the -O2 of dpkg's build flags, so CVODE's own work per step (the
# Nordsieck predictor, the vector operations, the error test) runs as -O0
# code: a quarter of the spinning egg's instructions, 7 % of the default ride
# (bench/README.md, "CVODE built with optimisation"). The same source and
# patches, from Debian's archive (the .dsc's checksum pinned here; dpkg-source
# checks the tarballs against it), compiled with -O2 (no -ffast-math, no
# -march: the same arithmetic, results bit for bit the same), CVODE and what
# slidesim links only, static, into SLIDESIM_SUNDIALS_PREFIX, where CMake
# looks first (CMakeLists.txt).
sundials_version=6.4.1+dfsg1-3
sundials_dsc_sha256=f431a056ef33e85f331cfb1611da444fd5ff3d03873b6dec0cfdb319b8c972ab
prefix=${SLIDESIM_SUNDIALS_PREFIX:-/opt/slidesim-deps/sundials-$sundials_version}
mirror=${SLIDESIM_DEBIAN_MIRROR:-http://deb.debian.org/debian}
if [ ! -f "$prefix/.complete" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  echo "building CVODE $sundials_version with -O2 from Debian's source package into $prefix"
  dsc=sundials_$sundials_version.dsc
  (
    cd "$work"
    fetch() {
      curl -fsS -O "$mirror/pool/main/s/sundials/$1" ||
        { echo "error: cannot download $mirror/pool/main/s/sundials/$1 (SLIDESIM_DEBIAN_MIRROR)" >&2; exit 1; }
    }
    fetch "$dsc"
    echo "$sundials_dsc_sha256  $dsc" | sha256sum -c --quiet - ||
      { echo "error: $mirror/pool/main/s/sundials/$dsc is not the pinned Debian source package" >&2; exit 1; }
    for f in $(awk '/^Files:/{f=1; next} /^[^ ]/{f=0} f{print $3}' "$dsc"); do
      fetch "$f"
    done
    # checks every file against the .dsc (its signature cannot be checked
    # without debian-keyring: the .dsc's own checksum above stands for it)
    dpkg-source --no-copy -x "$dsc" source >>log 2>&1 || { tail -20 log >&2; exit 1; }
    cmake -S source -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_FLAGS_RELEASE="-O2 -DNDEBUG" \
      -DCMAKE_Fortran_FLAGS_RELEASE="-O2" -DCMAKE_Fortran_COMPILER=gfortran \
      -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_INSTALL_LIBDIR=lib -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
      -DBUILD_SHARED_LIBS=OFF -DBUILD_STATIC_LIBS=ON -DBUILD_FORTRAN_MODULE_INTERFACE=ON \
      -DBUILD_CVODE=ON -DBUILD_ARKODE=OFF -DBUILD_CVODES=OFF -DBUILD_IDA=OFF -DBUILD_IDAS=OFF \
      -DBUILD_KINSOL=OFF -DENABLE_MPI=OFF -DENABLE_OPENMP=OFF -DENABLE_PTHREAD=OFF \
      -DEXAMPLES_ENABLE_C=OFF -DEXAMPLES_ENABLE_CXX=OFF -DEXAMPLES_ENABLE_F2003=OFF \
      -DEXAMPLES_INSTALL=OFF >>log 2>&1 || { tail -20 log >&2; exit 1; }
    cmake --build build -j "$(nproc)" >>log 2>&1 || { tail -40 log >&2; exit 1; }
    need_root "CVODE into $prefix"
    $sudo cmake --install build >>log 2>&1 || { tail -20 log >&2; exit 1; }
    echo "$sundials_version -O2" | $sudo tee "$prefix/.complete" >/dev/null
  )
  rm -rf "$work"
  trap - EXIT
fi
