/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot: the per-atom parts of a dense bed around the pair loops
   (the contact masses, pass 1's lists, the film budget's tallies) and the ghost communication
   of per-atom sums, which the film budget, the contact-network check and the contact masses
   send through AtomVectorComm
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"

#include "atom.h"
#include "force.h"

#include <vector>

using namespace LAMMPS_NS;

// Owned atoms' inverse contact masses, then the ghosts' (a rigid body's mass is known to the
// owner of the atom only). Atoms change rank and index only when the lists are rebuilt.
void PairLubricatedSpringDashpot::update_inverse_mass()
{
  if (static_cast<int>(inverse_mass.size()) < atom->nlocal + atom->nghost) inverse_mass.resize(atom->nmax);
  contact_mass.fill(inverse_mass.data());
  exchange.forward(inverse_mass.data(), 1);
}

// Pass 1's lists grow to 5/4 of what they need (a few regrowths in a run's first step), not to
// twice: the set-up keeps every pair in the film's reach, the steps fewer. Exactly that size
// (resize alone would at least double the capacity).
void PairLubricatedSpringDashpot::grow_pair_lists(std::vector<int> &list_i, std::vector<int> &list_j,
                                                  std::vector<int> *list_jj, int need)
{
  const std::size_t size = need + need / 4;
  for (std::vector<int> *list : {&list_i, &list_j, list_jj})
    if (list) {
      list->reserve(size);
      list->resize(size);
    }
}

// The film budget's corrections (film_budget/film_budget.h) in the energy and virial.
void PairLubricatedSpringDashpot::tally_film_correction(int i, int j, double fpair, double delx, double dely,
                                                        double delz)
{
  ev_tally(i, j, atom->nlocal, force->newton_pair, 0.0, 0.0, fpair, delx, dely, delz);
}

void PairLubricatedSpringDashpot::tally_film_correction_xyz(int i, int j, double fx, double fy, double fz, double delx,
                                                            double dely, double delz)
{
  ev_tally_xyz(i, j, atom->nlocal, force->newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
}

int PairLubricatedSpringDashpot::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  return exchange.pack_forward(n, list, buf);
}

void PairLubricatedSpringDashpot::unpack_forward_comm(int n, int first, double *buf)
{
  exchange.unpack_forward(n, first, buf);
}

int PairLubricatedSpringDashpot::pack_reverse_comm(int n, int first, double *buf)
{
  return exchange.pack_reverse(n, first, buf);
}

void PairLubricatedSpringDashpot::unpack_reverse_comm(int n, int *list, double *buf)
{
  exchange.unpack_reverse(n, list, buf);
}
