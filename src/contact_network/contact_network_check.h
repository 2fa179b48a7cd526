/* -*- c++ -*- ----------------------------------------------------------
   The stability check of the network of sustained contacts for pair_style
   lubricated/springdashpot (the bounds: lubricated/contact_network.h): at the first step of a
   run and every network_check_interval steps, only where some type pair's (or wall's) contact
   load exceeds network_check_load. Per atom the network sums over its contacts in overlap now
   and a step ago (pairs and walls, summed over ranks), then each contact's bounds; the worst
   over all ranks decides between nothing, a WARNING (once a run) and an ERROR.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_CONTACT_NETWORK_CHECK_H
#define LMP_LUBRICATED_CONTACT_NETWORK_CHECK_H

#include "pointers.h"

#include "contact_network/contact_network_participant.h"
#include "lubricated/contact.h"
#include "lubricated/film_solve.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

class ContactNetworkCheck : protected Pointers {
 public:
  // style: the pair style's name for the messages.
  ContactNetworkCheck(LAMMPS *lmp, class AtomVectorComm &exchange, const char *style) :
      Pointers(lmp), exchange(exchange), style(style)
  {
  }

  // The per type pair loads for ntypes types (the pair style's allocate).
  void allocate(int ntypes);
  // A run's start (init_style): the checks begin at its first step; set_loads turns them on.
  void start_run();
  // The loads of a sustained contact of types i, j (contact_network.h), from its model and the
  // time step (init_one and each new time step).
  void set_loads(int i, int j, const lubricated::ContactModel &model);
  // At each set-up: the participants (the wall fixes), whose sustained contacts join the check
  // and whose loads may turn it on.
  void find_participants();
  // Whether this step checks (the pair loop then selects its candidates in one piece); moves
  // the next check on.
  bool due();

  // What the check reads of the pair style: the candidate pairs of the step (in overlap or
  // not), the inverse contact masses where some atom is immovable (else nullptr), the
  // velocities over the last step under fix nve/sphere/midpoint (else nullptr: v), and the
  // coefficients per type pair (for the message); the films the coupled solve took at this step
  // (count 0: none): a contact whose own film it solved counts with it (contact_network.h).
  struct Pairs {
    const int *i, *j;
    int n;
    const double *inverse_mass;
    class FixNVESphereMidpoint *midpoint;
    const lubricated::Coefficients *coeffs;
    lubricated::SolvedFilms solved;
  };
  void check(const Pairs &pairs);

  double memory_usage() const;

 private:
  class AtomVectorComm &exchange;
  const char *style;
  int stride = 1;                     // type pair (i, j) at i * stride + j
  std::vector<double> load, bound;    // per type pair: the normal load and the bounding one
  bool on = false, warned = false;
  bigint next = 0;                                         // step of the next check
  std::vector<double> sums;                                // per atom (lubricated::network_values each)
  std::vector<int> network_i, network_j;                   // this check's sustained pair contacts
  std::vector<double> network_bound, network_relief;       // and their bounding loads and films' reliefs
  std::unordered_map<long long, double> solved_damping;    // pair (i, j) -> its solved film's c_n
  void find_solved_films(const Pairs &pairs);
  double own_film(int i, int j) const;
  struct Participant {
    ContactNetworkParticipant *contacts;
    class Fix *fix;
  };
  std::vector<Participant> participants;
  bool participants_on = false;
  // This check's wall contacts: owned atom, normal, participant.
  struct WallContact {
    int i, wall;
    double n[3];
    double bound, relief;    // its bounding load (relieved) and its own solved film's relief 2 a
  };
  struct WallFilm {    // a wall's film in the solve: the normal from the wall, the damping
    double n[3];
    double damping;
  };
  std::unordered_multimap<int, WallFilm> solved_wall_films;    // by owned atom
  double own_wall_film(int i, const double *n) const;
  double relieved_bound(double load, double bound, double c, double mass) const;
  std::vector<WallContact> wall_contacts;
  std::vector<double> wall_load, wall_bound;

  double mass(const Pairs &pairs, int i) const;
  double pair_mass(const Pairs &pairs, int i, int j) const;
  void sum_pair_contacts(const Pairs &pairs);
  void sum_wall_contacts(const Pairs &pairs);
  void score_and_report(const Pairs &pairs);
  void describe(int k, int *types, long long *tags, double *contacts) const;
};

}    // namespace LAMMPS_NS

#endif
