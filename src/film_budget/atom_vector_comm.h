/* -*- c++ -*- ----------------------------------------------------------
   Ghost communication of per-atom vectors for the parts of pair_style lubricated/springdashpot
   that sum over the atoms of several ranks (the film budget, the contact-network check, the
   contact masses): forward copies each owned atom's values onto its ghosts, reverse adds each
   ghost's values to its owner's. Any vector, any number of times within a step; the pair style's
   pack/unpack_forward/reverse_comm callbacks delegate here.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_ATOM_VECTOR_COMM_H
#define LMP_LUBRICATED_ATOM_VECTOR_COMM_H

#include "pointers.h"

#include <algorithm>

namespace LAMMPS_NS {

class AtomVectorComm : protected Pointers {
 public:
  // pair: the pair style whose callbacks delegate here; its comm_forward and comm_reverse must
  // hold the widest vector sent.
  AtomVectorComm(LAMMPS *lmp, class Pair *pair) : Pointers(lmp), pair(pair) {}

  // values: width doubles per owned and ghost atom, atom k's at values[width * k].
  void forward(double *values, int width);
  void reverse(double *values, int width);

  int pack_forward(int n, const int *list, double *buf) const
  {
    for (int k = 0; k < n; k++)
      std::copy_n(values + width * list[k], width, buf + width * k);
    return width * n;
  }
  void unpack_forward(int n, int first, const double *buf) const
  {
    std::copy_n(buf, width * n, values + width * first);
  }
  int pack_reverse(int n, int first, double *buf) const
  {
    std::copy_n(values + width * first, width * n, buf);
    return width * n;
  }
  void unpack_reverse(int n, const int *list, const double *buf) const
  {
    for (int k = 0; k < n; k++)
      for (int q = 0; q < width; q++)
        values[width * list[k] + q] += buf[width * k + q];
  }

 private:
  class Pair *pair;
  double *values = nullptr;    // the vector in transit
  int width = 1;
};

}    // namespace LAMMPS_NS

#endif
