/* ----------------------------------------------------------------------
   Ghost communication of per-atom vectors (atom_vector_comm.h)
------------------------------------------------------------------------- */

#include "atom_vector_comm.h"

#include "comm.h"

using namespace LAMMPS_NS;

void AtomVectorComm::forward(double *vector, int vector_width)
{
  values = vector, width = vector_width;
  comm->forward_comm(pair);
}

void AtomVectorComm::reverse(double *vector, int vector_width)
{
  values = vector, width = vector_width;
  comm->reverse_comm(pair);
}
