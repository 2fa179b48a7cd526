/* -*- c++ -*- ----------------------------------------------------------
   The many-body film budget of pair_style lubricated/springdashpot (`limit atom`, the
   default): each film's share of its atoms' budget summed per owned and ghost atom, and the
   films of atoms over budget scaled down after the pair loops (the physics:
   lubricated/film_budget.h). The pair loops apply every film in full and record it here
   (record_film, record_films); the walls' films (FilmBudgetParticipant) join the loads and
   are scaled by the walls themselves. The sums over ranks go through AtomVectorComm, which
   can send any per-atom vector forward and back as often as a step needs.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_FILM_BUDGET_LAMMPS_H
#define LMP_LUBRICATED_FILM_BUDGET_LAMMPS_H

#include "pointers.h"

#include "film_budget/atom_vector_comm.h"
#include "film_budget/film_budget_participant.h"
#include "lubricated/contact.h"

#include <memory>
#include <vector>

namespace lubricated {
struct SolvedFilms;
}

namespace LAMMPS_NS {

// `limit implicit` (film_solve_step.h): the films of atoms over budget solved together.
struct FilmSolveSettings {
  bool on = false;
  double tolerance = 1e-8;    // relative residual (lubricated/film_solve.h)
  int max_iterations = 200;
};

// The centre distance within which atoms i and j can act before the next neighbor list build:
// their radii, the types' largest film reach (max_reach, per type pair) and the skin (each atom
// moves at most half of it until then). The film budget's bound and the list trim's.
inline double reach_until_next_build(const double *radius, const int *type, const double *max_reach, int stride, int i,
                                     int j, double skin)
{
  return radius[i] + radius[j] + max_reach[type[i] * stride + type[j]] + skin;
}

class FilmBudget : protected Pointers {
 public:
  FilmBudget(LAMMPS *lmp, AtomVectorComm &exchange);
  ~FilmBudget() override;

  // At init_style: the participants (every fix that is one), and whether the budget is kept:
  // under `limit atom` where a pair or a participant has films. shear_films: some type pair
  // has a shear film, which shares the budget; roll_films: some type pair has a rolling film,
  // which shares it too.
  // solve: `limit implicit` (limit_per_atom too), the films of atoms over budget solved.
  void init(bool limit_per_atom, bool wet_pairs, bool shear_films, const FilmSolveSettings &solve = {},
            bool roll_films = false);
  bool kept() const { return enabled; }
  // `limit implicit` with the budget kept: the films of atoms over budget are solved, the
  // participants' with them.
  bool solves() const { return enabled && solve_on; }
  bool wet_participants() const { return any_wet_participant; }
  // This step's: whether the films can exceed any atom's budget (else nothing is recorded or
  // scaled), and an owned atom's film scale once finish() computed it.
  bool active() const { return now; }
  // Before begin_step (a participant's pre_force): whether this step can be active(): it was at
  // the last step, or the bounds are made again now (begin_step).
  bool may_be_active() const;
  double scale(int i) const { return now ? scale_of_atom[i] : 1.0; }
  bool records_shear() const { return shear_records; }

  // What the bounds read per type pair (index type_i * stride + type_j).
  struct TypeTables {
    const lubricated::ContactModel *models;
    const double *max_reach;
    int stride;
  };
  // Before the pair loops: whether this step keeps the budget (from the bounds of the pairs of
  // the neighbor list, recomputed at each build, set-up or larger time step), and if so the
  // loads started from the participants' films.
  void begin_step(const class NeighList *list, const TypeTables &tables);
  // Room for `more` records before a piece of the pair loops.
  void reserve_records(int more);

  // A pair's film (its size along n) and its share of the budget.
  __attribute__((always_inline)) inline void record_film(int i, int j, double film, double share, int nlocal,
                                                         int newton_pair)
  {
    load_of_atom[i] += share;
    if (newton_pair || j < nlocal) load_of_atom[j] += share;
    record_i[nrecord] = i;
    record_j[nrecord] = j;
    record_force[nrecord] = film;
    nrecord += film != 0.0;
  }
  // With shear or rolling films (records_shear()): the shear film's force on i too, the rolling
  // film's torque on i where kept, and the contact's share, the larger of the normal film's and
  // the tangential films' (lubricated/film_budget.h); all films are scaled by the same s.
  __attribute__((always_inline)) inline void record_films(int i, int j, double film, const lubricated::Vec3 &shear,
                                                          double share, int nlocal, int newton_pair,
                                                          const lubricated::Vec3 &roll = {})
  {
    load_of_atom[i] += share;
    if (newton_pair || j < nlocal) load_of_atom[j] += share;
    record_i[nrecord] = i;
    record_j[nrecord] = j;
    record_force[nrecord] = film;
    double *out = &record_shear[3 * nrecord];
    out[0] = shear.x, out[1] = shear.y, out[2] = shear.z;
    bool any = (film != 0.0) | (shear.x != 0.0) | (shear.y != 0.0) | (shear.z != 0.0);
    if (roll_records) {
      double *torque = &record_roll[3 * nrecord];
      torque[0] = roll.x, torque[1] = roll.y, torque[2] = roll.z;
      any |= (roll.x != 0.0) | (roll.y != 0.0) | (roll.z != 0.0);
    }
    nrecord += any;
  }

  // What the correction pass tallies (the pair style's energy and virial).
  class Tally {
   public:
    virtual void tally_film_correction(int i, int j, double fpair, double delx, double dely, double delz) = 0;
    virtual void tally_film_correction_xyz(int i, int j, double fx, double fy, double fz, double delx, double dely,
                                           double delz) = 0;

   protected:
    ~Tally() = default;
  };
  // After the pair loops (where active()): the loads summed on the owners, the scales sent to
  // the ghosts, and the recorded films of atoms over budget scaled down. inverse_mass: the
  // contact masses' inverses where some atom is immovable (its load limits nothing), else
  // nullptr; tally: where the pair style tallies, else nullptr.
  // With `limit implicit` (step given) those films are solved instead (film_solve_step.h), at
  // the velocities the evaluation took (owned and ghost) over kick_time.
  struct StepInputs {
    double **v, **omega;
    double kick_time;
    const double *inverse_mass;
  };
  void finish(const double *inverse_mass, Tally *tally, const StepInputs *step = nullptr);
  // The coupled solve of this evaluation: its iterations and this rank's solved films (0: none).
  int solve_iterations() const;
  int solved_films() const;
  // What the solve taken at this step took (film_solve_step.h; nothing where none was).
  lubricated::SolvedFilms solved_now() const;

  double memory_usage() const;

 private:
  AtomVectorComm &exchange;
  bool limit_per_atom = true, enabled = false, shear_records = false, roll_records = false, any_wet_participant = false;
  bool solve_on = false;
  std::unique_ptr<class FilmSolveStep> solve_step;
  TypeTables tables{};    // begin_step's, for the solve's coefficients
  std::vector<FilmBudgetParticipant *> participants;
  // Per owned and ghost atom: the summed film share and its scale.
  std::vector<double> load_of_atom, scale_of_atom;
  // Per pair with a film: i, j, its film force along n, with shear films the shear film's
  // force and with rolling films the rolling film's torque on i (3 per record each).
  std::vector<int> record_i, record_j;
  std::vector<double> record_force, record_shear, record_roll;
  int nrecord = 0;
  bool now = false;
  double bound_dt = 0.0;    // the time step the bounds were computed for
  void grow_atoms();
  bool bounds_due() const;
  bool films_can_exceed_budget(const class NeighList *list, const TypeTables &tables);
  template <class BoundOf> bool sum_bounds_can_exceed(const class NeighList *list, BoundOf &&bound_of);
  void scale_films(Tally *tally);
  void scale_films_and_shear(Tally *tally);
};

}    // namespace LAMMPS_NS

#endif
