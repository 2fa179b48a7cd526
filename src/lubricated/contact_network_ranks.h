// The contact-network check's decision over MPI ranks (contact_network.h), shared by the LAMMPS
// pair style and the LIGGGHTS model: each rank scores its contacts, the worst over all ranks
// decides between nothing, a WARNING (once a run) and an ERROR, and the owner of the worst
// contact describes it for every rank's message. Only MPI here, no engine.
#pragma once

#include "lubricated/contact_network.h"
#include "lubricated/contact_network_message.h"

#include <algorithm>
#include <mpi.h>

namespace lubricated {

// One rank's contacts, scored one by one with add().
class NetworkScores {
 public:
  explicit NetworkScores(int rank) : lower_{0.0, rank}, upper_{0.0, rank} {}

  // Contact k's lower bound (Rayleigh quotient) and upper bound (Gershgorin row) with the load
  // that bounds it.
  void add(int k, double lower, double upper, double bound_load)
  {
    if (lower > lower_.value) lower_.value = lower, worst_lower_ = k;
    if (upper > upper_.value) upper_.value = upper, worst_upper_ = k;
    unit_upper_ = std::max(unit_upper_, upper / bound_load);
  }

  // Collective. False where nothing is to be said (stable, or likely unstable but already
  // warned); else fills `found`, asking describe(k, types[2], tags[2], contacts[2]) about the
  // worst contact k on the rank that holds it, and sets `warned` for a warning.
  template <class Describe> bool decide(MPI_Comm world, bool &warned, Describe describe, NetworkFinding &found) const
  {
    Score reduced;
    MPI_Allreduce(&lower_, &reduced, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
    const bool unstable = reduced.value >= stable_network_load;
    if (!unstable) {
      if (warned || reduced.value < likely_unstable_network_load) return false;
      MPI_Allreduce(&upper_, &reduced, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
      if (reduced.value < stable_network_load) return false;
      warned = true;
    }
    double info[7] = {0.0};    // load, types, tags, contacts of the worst contact
    const int worst = unstable ? worst_lower_ : worst_upper_;
    if (lower_.rank == reduced.rank && worst >= 0) {
      int types[2];
      long long tags[2];
      double contacts[2];
      describe(worst, types, tags, contacts);
      info[0] = reduced.value;
      info[1] = std::min(types[0], types[1]);
      info[2] = std::max(types[0], types[1]);
      info[3] = static_cast<double>(tags[0]);
      info[4] = static_cast<double>(tags[1]);
      info[5] = contacts[0];
      info[6] = contacts[1];
    }
    MPI_Bcast(info, 7, MPI_DOUBLE, reduced.rank, world);
    found.unstable = unstable;
    found.load = info[0];
    found.type_i = static_cast<int>(info[1]);
    found.type_j = static_cast<int>(info[2]);
    found.tag_i = static_cast<long long>(info[3]);
    found.tag_j = static_cast<long long>(info[4]);
    found.contacts_i = info[5];
    found.contacts_j = info[6];
    MPI_Allreduce(&unit_upper_, &found.largest_unit_upper, 1, MPI_DOUBLE, MPI_MAX, world);
    MPI_Allreduce(&lower_.value, &found.largest_lower, 1, MPI_DOUBLE, MPI_MAX, world);
    return true;
  }

 private:
  struct Score {
    double value;
    int rank;
  };
  Score lower_, upper_;
  int worst_lower_ = -1, worst_upper_ = -1;
  double unit_upper_ = 0.0;
};

}    // namespace lubricated
