/* -*- c++ -*- ----------------------------------------------------------
   pair_style lubricated/springdashpot: the collision model of Brandle de Motta et al.
   (CFM 2011) for finite-size spheres. A thin adapter: neighbour loop, ghost data,
   tallies and restart; the physics lives in src/lubricated/. The many-body film budget
   (film_budget/film_budget.h) and the contact-network check
   (contact_network/contact_network_check.h) are classes of their own, which the wall fixes
   reach through interfaces (film_budget_participant.h, contact_network_participant.h).
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_LUBRICATED_SPRINGDASHPOT_H
#define LMP_PAIR_LUBRICATED_SPRINGDASHPOT_H

#include "pair.h"

#include "contact_mass/contact_mass.h"
#include "contact_network/contact_network_check.h"
#include "film_budget/atom_vector_comm.h"
#include "film_budget/film_budget.h"
#include "lubricated/contact.h"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class PairLubricatedSpringDashpot : public Pair, public FilmBudgetOwner, private FilmBudget::Tally {
 public:
  PairLubricatedSpringDashpot(class LAMMPS *);
  ~PairLubricatedSpringDashpot() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void coeff(int, char **) override;
  void init_style() override;
  void init_list(int, class NeighList *) override;
  double init_one(int, int) override;
  void reset_dt() override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  double memory_usage() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  // The many-body film budget (film_budget/film_budget.h), for the wall fixes: whether it is
  // kept (the walls' loads included), and an owned atom's film scale of this step.
  const FilmBudget &film_budget() const override { return budget; }

 protected:
  std::vector<lubricated::Coefficients> coeffs;    // per type pair, (ntypes+1)^2
  std::vector<lubricated::ContactModel> models;    // derived from coeffs and dt
  std::vector<double> maxrad;                      // largest radius per type (this run's so far)
  std::vector<double> max_reach;                   // farthest film gap per type pair
  std::vector<double> cutoff_given;                // pair_coeff cutoff per type pair (0: from the radii)
  bool film_reach_uniform = true;                  // one max_reach for all (eval sets it)
  bool any_wet = false;
  bool any_tangential = false;                   // friction, rolling or shear film on some type pair
  bool any_roll_film = false;                    // a rolling film on some type pair (scalar loops only)
  class FixContactHistory *history = nullptr;    // tangential elongation per contact
  std::string history_id;
  // The placeholder (fix DUMMY) holding the history's place in the fix list while there is none.
  std::string history_slot_id() const { return history_id + "_SLOT"; }
  class FixNVESphereMidpoint *midpoint = nullptr;    // the paper's integrator, if in use
  class FixStepVelocity *step_velocity = nullptr;    // the last step's velocities for a set-up
  bool verlet_velocities = false;                    // fix nve/sphere integrates all (single())
  bool step_velocities_used = false;                 // the last evaluation took v^(n+1/2)
  bool continued = false;                            // this set-up continues the last run
  // The pair loops' own lists (eval): the list entries kept by pass 1 (candidate: i, j and with
  // friction, for the history, jj) and its film-only pairs (film), per atom its radius grown by
  // the bound on its move in one step (step_reach), and pass 2's grouping of a chunk by type
  // pair (vector_forces.h).
  struct LoopLists {
    std::vector<int> candidate_i, candidate_j, candidate_jj, film_i, film_j;
    std::vector<double> step_reach;
    std::vector<int> group_count, group_keys;
    double memory_usage() const;
  } loop_lists;
  void grow_pair_lists(std::vector<int> &list_i, std::vector<int> &list_j, std::vector<int> *list_jj, int need);
  // This evaluation's counts (compute pair, pvector): the pairs pass 1 selected (in contact,
  // within a step of it, in a film's reach, or holding an elongation) and, of those, the pairs
  // apart by more than both atoms move in the step, in a film's reach, holding no elongation
  // (their film alone acts).
  bigint selected_pairs = 0, film_only_pairs = 0;
  // No tangential parts, exact integration, velocity Verlet (and `vector yes`): pass 1 puts the
  // pairs that cannot touch within the step but are in the film in a list of their own, and
  // vector_pairs.h computes them, the pairs in sustained contact and the other pairs that stay
  // apart, vectorised, type pair by type pair unless one model serves all (uniform_models).
  bool vector_enabled = true;
  bool uniform_models = true;
  bool vector_loops = false;
  // Friction or rolling: the film-only pairs vectorised (normal and shear film), and the pairs in
  // sustained contact with friction (not rolling) that touched at the last step.
  bool film_loops = false;

  // Ghost communication of the per-atom sums below (the comm callbacks delegate to it).
  AtomVectorComm exchange;
  // Many-body film budget (`limit atom`, the default; `limit pair`: each pair's own cap only).
  bool limit_per_atom = true;
  FilmSolveSettings film_solve;    // `limit implicit` (film_budget/film_solve_step.h)
  void set_comm_sizes();
  void parse_film_solve_keyword(const std::string &key, const std::string &value);
  void finish_film_budget();
  void check_network();
  FilmBudget budget;
  void tally_film_correction(int i, int j, double fpair, double delx, double dely, double delz) override;
  void tally_film_correction_xyz(int i, int j, double fx, double fy, double fz, double delx, double dely,
                                 double delz) override;

  // Immovable atoms and rigid bodies (contact_mass.h): where a run has any, the inverse mass
  // a contact moves, per owned and ghost atom (0 immovable), rebuilt with the neighbor lists;
  // otherwise (inverse_mass_on false) m_e comes from rmass as it always did.
  ContactMass contact_mass;
  bool inverse_mass_on = false;
  std::vector<double> inverse_mass;
  void update_inverse_mass();
  // Stability of the network of sustained contacts (contact_network/contact_network_check.h).
  ContactNetworkCheck network;
  int network_candidates = -1;    // the candidates the check reads this step (-1: not due)

  // init_style's steps (pair_lubricated_springdashpot_init.cpp).
  void check_atom_style();
  struct TypePairNeeds {
    bool friction = false, shear_film = false, roll_film = false;
    std::set<std::string> advice;    // the set-up checks' warnings, once each
  };
  TypePairNeeds settle_coefficients();
  void keep_contact_history(bool any_friction);
  void warn_hybrid_instances();
  void find_integrators();
  void choose_loops();
  void init_film_budget(bool any_shear_film);
  void check_grid_spacing();
  void find_largest_radii();

  void allocate();
  int ntypes_alloc = 0;
  int index(int itype, int jtype) const { return itype * (ntypes_alloc + 1) + jtype; }
  void update_models();
  // The pair loops (pair_lubricated_springdashpot_eval.cpp): eval() is pass 1 (select_pairs(),
  // the entries that can act within the step) and pass 2 (evaluate_pair() on each, or the
  // vectorised vector_forces() with evaluate_pair() for the rest).
  template <bool WET, bool TANGENTIAL, bool SPLIT = false> void eval();
  void update_step_reach(double **v);
  // The wet list trimmed in place after each build to the pairs a film can reach before the
  // next (pair_lubricated_springdashpot_list.cpp); `trim no` keeps it as LAMMPS built it.
  bool trim_enabled = true;
  std::pair<bigint, bigint> trimmed_build{-1, -1};    // the build trimmed last (lastcall, ncalls)
  bool list_can_be_trimmed() const;
  void trim_list_to_reach();
  void trim_list_if_built();
  // At each build, before the trim: the radii as they are now (fix adapt may grow them during a
  // run) in maxrad and max_reach, and an error where this run's cutoffs no longer cover them.
  void follow_radii();
  double largest_film_reach(int i, int j) const;
  bool any_cutoff_given() const;
  std::string pair_coeff_words(int i, int j) const;    // write_data's words for type pair i j
  bool restart_cutoffs = false;                        // read_restart: the file holds a cutoff per type pair
  int restart_values = 0;                              // coefficient values per type pair in the restart file read
  static constexpr int values_with_rollfilm = 32;      // restart flag: the file holds rollfilm's value too
  template <bool WET, bool TANGENTIAL, bool SPLIT, bool UNIFORM_REACH>
  int select_pairs(int &next, int &nfilm, int limit);
  static constexpr int pairs_per_piece = 4096;    // pass 1's pieces (16 chunks of vector_forces)
  // The overlap check (lubricated/overlap_check.h): any_deep_overlap finds a piece where a pair overlaps
  // by more than overlap_depth of the smaller radius (the warning's fraction, the error's once
  // warned: overlap_warned, reset at init); check_pair_overlaps then names the deepest pair.
  double overlap_depth = 0.1;
  bool overlap_warned = false, overlap_deep_warned = false;
  // Due at a run's set-up and every overlap_check_interval steps: an overlap beyond the limits
  // builds up over several steps of a contact lasting N_c of them.
  static constexpr int overlap_check_interval = 4;
  bool overlap_check_due = false;
  bool any_deep_overlap(int ncandidate) const;
  void check_pair_overlaps(int ncandidate);
  // What every pair of one eval() reads, gathered once per call.
  struct PairLoop {
    double **x, **v, **f, **torque, **omega;
    const double *radius, *rmass, *inverse;    // inverse: inverse masses, or nullptr (rmass)
    const int *type;
    const lubricated::ContactModel *models;
    int stride, nlocal, newton_pair;
    double dt, kick_time;    // kick_time: the film budget's (film_budget.h)
    lubricated::Evaluation when;
    bool budget;    // this step keeps the film budget
    bool steps;     // a step, not a set-up: time passes (contact histories advance)
  };
  PairLoop pair_loop(double **v, bool wet) const;
  void find_uniform_film_reach();
  template <bool WET, bool TANGENTIAL>
  __attribute__((always_inline)) inline void evaluate_pair(const PairLoop &loop, int i, int j, int jj);
  __attribute__((always_inline)) inline void set_tangential_point(const PairLoop &loop, int i, int j, int jj,
                                                                  const lubricated::ContactModel &model,
                                                                  lubricated::ContactPoint &p,
                                                                  lubricated::HistorySlot &slot);
  template <bool WET, bool TANGENTIAL>
  __attribute__((always_inline)) inline void contact(const PairLoop &loop, int i, int j, int jj,
                                                     const lubricated::ContactModel &model, lubricated::ContactPoint &p,
                                                     const double *del, double rinv);
  template <bool TANGENTIAL>
  __attribute__((always_inline)) inline void apply_pair_force(const PairLoop &loop, int i, int j, const double *del,
                                                              double fpair, const lubricated::Vec3 &tangential,
                                                              double energy);
  __attribute__((always_inline)) inline void forget_history(int i, int jj);
  // Pass 2's vectorised loops over one piece (vector_forces.h).
  template <bool TANGENTIAL, class Evaluate> class VectorForces;
  template <bool TANGENTIAL, class Evaluate>
  void vector_forces(int ncandidate, int nfilm, double **v, double **omega, Evaluate &evaluate);
};

}    // namespace LAMMPS_NS

#endif
