/* -*- c++ -*- ----------------------------------------------------------
   The film force of pairs that stay apart over the coming step (pair style
   lubricated/springdashpot, its wet loop): no contact can act, so the force is the film's
   alone, lubricated::film_force_apart, in a loop without branches that the compiler
   vectorises (gathers of the atoms' data), for the instruction set found at load time.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_FILM_ONLY_PAIRS_H
#define LMP_LUBRICATED_FILM_ONLY_PAIRS_H

#include "lubricated/lubrication.h"

namespace LAMMPS_NS {
namespace film_only_pairs {

  // Per-atom data: x and v 3 per atom, contiguous (LAMMPS's x[0], v[0]).
  struct Atoms {
    const double *x, *v, *radius, *rmass;
  };

  // fpair[c] = F_l / r for the pairs (pair_i[c], pair_j[c]), c < n, all with the active
  // film `film`: the force on i is fpair (x_i - x_j), on j the opposite.
  void forces(const Atoms &atoms, const lubricated::Lubrication &film, double dt,
              const int *pair_i, const int *pair_j, int n, double *fpair);

}    // namespace film_only_pairs
}    // namespace LAMMPS_NS

#endif
