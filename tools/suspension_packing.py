"""The packing of examples/suspension_shear for runs that shear it apart from the example
(tests/lammps/suspension_scene.py, bench/film_solve_cost.py): the example's own input up to its
shear stage, so the packing follows the example, ending with write_data packing.data."""
import pathlib

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "examples" / "suspension_shear" / "in.suspension_shear"


def packing_script():
    """The example's input up to its shear stage, ending with write_data packing.data."""
    text = EXAMPLE.read_text()
    return text[:text.index("# 2. Simple shear")] + "write_data packing.data nocoeff\n"
