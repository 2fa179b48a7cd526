// liggghts-lubricated: LIGGGHTS's own driver (one LAMMPS instance reading the input), linked to
// liblubricated_liggghts.so so that `model lubricated` is registered without LD_PRELOAD.
#include <mpi.h>

#include "input.h"
#include "lammps.h"

extern "C" const char *lubricated_liggghts_version();

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  (void)lubricated_liggghts_version();    // keeps the model library linked
  LAMMPS_NS::LAMMPS *lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
