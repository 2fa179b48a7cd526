#!/usr/bin/env bash
# Debian's LIGGGHTS 3.8.0 for `model lubricated`: the liggghts binary, its headers and library,
# and Open MPI (its MPI, with mpi.h for the build). Installed when run as root; otherwise the
# missing packages are named and the LIGGGHTS build and tests are skipped (not an error).
set -euo pipefail
arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)

missing=()
command -v liggghts >/dev/null || missing+=(liggghts)
[ -f /usr/include/liggghts/contact_models.h ] || missing+=(libliggghts-dev)
[ -f "/usr/lib/$arch/openmpi/include/mpi.h" ] || missing+=(libopenmpi-dev)
command -v mpirun.openmpi >/dev/null || missing+=(openmpi-bin)
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" = 0 ]; then
  echo "setup: installing Debian packages for LIGGGHTS: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  if ! { apt-get update -qq && apt-get install -y -qq "${missing[@]}" >/dev/null; }; then
    echo "setup: SKIPPING LIGGGHTS (model lubricated): apt-get could not install ${missing[*]}" >&2
  fi
else
  echo "setup: SKIPPING LIGGGHTS (model lubricated): missing Debian packages ${missing[*]};" \
       "run 'sudo apt-get install ${missing[*]}' or make as root to build and test it" >&2
fi
