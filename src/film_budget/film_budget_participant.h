/* -*- c++ -*- ----------------------------------------------------------
   The two sides of the many-body film budget (film_budget.h) that other styles see, so that
   neither includes the other: a fix whose films share the atoms' budget (the plugin's wall
   fixes) is a FilmBudgetParticipant, found by the budget at init; the pair style that keeps
   the budget is a FilmBudgetOwner, through which such a fix reads the scale of its films.
   Under `limit implicit` a participant's films of atoms over budget join the coupled film
   solve (film_solve_step.h) as wall links, and take back the solved forces.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_FILM_BUDGET_PARTICIPANT_H
#define LMP_LUBRICATED_FILM_BUDGET_PARTICIPANT_H

#include "lubricated/film_solve.h"

#include <vector>

namespace LAMMPS_NS {

class FilmBudgetParticipant {
 public:
  // Whether this fix has films at all.
  virtual bool wet() const = 0;
  // Adds this step's film shares to the owned atoms' loads (computed before the pair style).
  virtual void add_film_loads(double *load, int nlocal) const = 0;
  // Adds to each owned atom the bound on its film shares until the next neighbor list build.
  virtual void add_film_share_bounds(double *bound, int nlocal) const = 0;
  // The coupled film solve: appends this step's films of the owned atoms whose budget scale is
  // below 1 as links (j = -1, lubricated/film_solve.h) at the velocities the evaluation took, and
  // returns how many; then takes their solved forces and torques on the atoms, in that order,
  // in place of their step-exact films.
  virtual int add_film_links(const double * /*scale*/, std::vector<lubricated::FilmLink> & /*links*/) { return 0; }
  virtual void take_solved_films(const lubricated::FilmLinkForce * /*solved*/, int /*count*/) {}

 protected:
  ~FilmBudgetParticipant() = default;
};

class FilmBudgetOwner {
 public:
  virtual const class FilmBudget &film_budget() const = 0;

 protected:
  ~FilmBudgetOwner() = default;
};

}    // namespace LAMMPS_NS

#endif
