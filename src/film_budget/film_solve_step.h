/* -*- c++ -*- ----------------------------------------------------------
   The coupled film solve of pair_style lubricated/springdashpot (`limit implicit`,
   doc/film_solve.rst): after the pair loops, the films of the atoms whose film budget binds
   (load D > 1) are taken out of the step-exact forces and solved together, implicitly, by the
   kernel's preconditioned conjugate gradients (lubricated/film_solve.h), the wall fixes' films
   of those atoms with them (FilmBudgetParticipant's links); the films of atoms within their
   budget keep the step-exact per-pair form. Called by FilmBudget::finish.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_FILM_SOLVE_STEP_H
#define LMP_LUBRICATED_FILM_SOLVE_STEP_H

#include "pointers.h"

#include "film_budget/film_budget.h"
#include "film_budget/implicit_drag.h"
#include "lubricated/film_solve.h"

#include <vector>

namespace LAMMPS_NS {

class FilmSolveStep : protected Pointers {
 public:
  FilmSolveStep(LAMMPS *lmp, AtomVectorComm &exchange) : Pointers(lmp), exchange(exchange) {}

  void configure(const FilmSolveSettings &settings);
  // At each run's init: the non-convergence warning may be given again; the fix whose drag the
  // solve takes implicitly (implicit_drag.h), if any; the budget's participants (the wet walls),
  // whose films of atoms over budget join the solve.
  void start_run(const std::vector<FilmBudgetParticipant *> &participants);
  // Before each evaluation's finish: no solve yet.
  void clear_counts() { iterations = 0, solved = 0; }
  int last_iterations() const { return iterations; }
  int last_solved_films() const { return solved; }    // this rank's
  // The films of the solve taken at this step (lubricated::SolvedFilms; none where none was).
  lubricated::SolvedFilms solved_at(bigint step) const;

  // The pair loops' records of this step (FilmBudget's): i, j, the film along n, and with shear
  // films the shear film's force on i (3 per record, else nullptr).
  struct Records {
    const int *i, *j;
    const double *film, *shear;
    int count;
    const double *roll = nullptr;    // the rolling films' torques on i (3 per record), where kept
  };
  // The films of every record with an atom whose scale (owned and ghost) is below 1 are solved
  // at the velocities the evaluation took, their step-exact forces replaced by the solved ones.
  void solve(const Records &records, const double *scale, const FilmBudget::TypeTables &tables,
             const FilmBudget::StepInputs &step, FilmBudget::Tally *tally);

  double memory_usage() const;

 private:
  AtomVectorComm &exchange;
  lubricated::FilmSolveOptions options;
  lubricated::FilmSolver solver;
  bool warned = false;
  int iterations = 0, solved = 0;
  // The warm start (lubricated::film_increment_guess): the owned atoms' increments of the step
  // before the last (x_{n-2}), and how many of the last steps' are known (the solves in a row
  // at the last step, whose atoms kept their indices); the step whose preconditioner blocks the
  // solver keeps, for at most blocks_kept_steps along such a chain.
  std::vector<double> previous_increment;
  bigint last_solve_step = -1, blocks_step = -1;
  static constexpr int blocks_kept_steps = 10;
  int known_increments = 0, last_nlocal = -1;
  std::vector<tagint> last_tags;    // the owned atoms of the last solve, in its order
  void start_from_last_steps();
  void carry_increments_by_tag();
  // Solved here first (the pairs', then the walls'), then (newton off) the others' copies.
  std::vector<lubricated::FilmLink> links;
  std::vector<int> link_record;    // each pair link's record
  std::vector<FilmBudgetParticipant *> walls;
  struct WallLinks {
    FilmBudgetParticipant *wall;
    int first, count;    // in links
  };
  std::vector<WallLinks> wall_links;
  std::vector<lubricated::FilmLinkForce> wall_solved;
  int collect_wall_links(const double *scale);
  void apply_solved_wall_films(const lubricated::FilmAtoms &atoms);
  std::vector<double> inverse_mass, inverse_inertia, velocity, other_force, increment;
  ImplicitDragParticipant *drag_fix = nullptr;
  std::vector<double> drag, rotational_drag;    // per owned atom, where drag_fix acts this step
  bool add_implicit_drag();
  int collect_links(const Records &records, const double *scale, const FilmBudget::TypeTables &tables);
  void gather_atoms(const FilmBudget::StepInputs &step);
  void gather_other_forces(const Records &records);
  void apply_solved_films(const Records &records, const lubricated::FilmAtoms &atoms, FilmBudget::Tally *tally);
};

}    // namespace LAMMPS_NS

#endif
