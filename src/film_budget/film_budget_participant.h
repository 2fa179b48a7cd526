/* -*- c++ -*- ----------------------------------------------------------
   The two sides of the many-body film budget (film_budget.h) that other styles see, so that
   neither includes the other: a fix whose films share the atoms' budget (the plugin's wall
   fixes) is a FilmBudgetParticipant, found by the budget at init; the pair style that keeps
   the budget is a FilmBudgetOwner, through which such a fix reads the scale of its films.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_FILM_BUDGET_PARTICIPANT_H
#define LMP_LUBRICATED_FILM_BUDGET_PARTICIPANT_H

namespace LAMMPS_NS {

class FilmBudgetParticipant {
 public:
  // Whether this fix has films at all.
  virtual bool wet() const = 0;
  // Adds this step's film shares to the owned atoms' loads (computed before the pair style).
  virtual void add_film_loads(double *load, int nlocal) const = 0;
  // Adds to each owned atom the bound on its film shares until the next neighbor list build.
  virtual void add_film_share_bounds(double *bound, int nlocal) const = 0;

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
