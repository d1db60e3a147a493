#!/usr/bin/env bash
# Installs what slidesim needs from Debian's packages (Debian 12): compiler, CMake,
# LAPACK, MINPACK, SUNDIALS, HDF5 and, for the Python scripts, numpy, h5py,
# matplotlib and scipy (Debian's scipy 1.10.1 regenerates the FITPACK tables),
# pint and udunits-bin (the tests parse the units in result files), xarray
# with h5netcdf (the tests open every result group with it), ParaView (the
# tests open every XDMF file with its XDMF reader) and Open MPI (sweeps across
# ranks: mpirun -n N slidesim sweep.nml; the build works without it).
# Idempotent: installs only what is missing.
set -euo pipefail

packages=(gfortran cmake make liblapack-dev libblas-dev minpack-dev
          libsundials-dev libsundials-fortran-dev libhdf5-dev hdf5-tools libopenmpi-dev openmpi-bin
          python3 python3-numpy python3-h5py python3-matplotlib python3-scipy python3-pint
          python3-xarray python3-h5netcdf udunits-bin paraview python3-paraview)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

sudo=""
if [ "$(id -u)" != 0 ]; then
  command -v sudo >/dev/null || { echo "error: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
echo "installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
