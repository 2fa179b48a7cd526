// The film-only pair loop of both engines: pairs near contact whose film alone acts over the
// coming step (film_force_apart, a step of the exact model with an active film), in one loop
// without branches or calls that the compiler vectorises. The LAMMPS pair style runs it over the
// pairs it has sorted as apart (vector_pairs.cpp); LIGGGHTS over its close pairs, which the loop
// also sorts (CLASSIFY: close_pairs.cpp). The caller compiles its entry points with
// LUBRICATED_VECTOR_CLONES (vector_clones.h).
#pragma once

#include "film_budget.h"
#include "normal_model.h"
#include "pair_geometry.h"

#include <cmath>

namespace lubricated {

// What CLASSIFY finds of a pair: the model does not act on it within the step (idle), it stays
// apart over the step (apart: the film force given here), or a contact may start within the
// step (general: for the caller's per-pair evaluation; force 0 here).
enum FilmPairState : int { film_pair_idle = 0, film_pair_apart = 1, film_pair_general = 2 };

// Per pair c < n of (pair_i[c], pair_j[c]): the film force on i (force_x/y/z; on j the opposite),
// its size along n (film_force) and the capacity m_e |u_n| (film_budget.h). GRID: the film has a
// grid spacing; INVERSE: m_e from the inverse contact masses (pair_geometry); CLASSIFY: state[c]
// as FilmPairState, the force 0 where not apart (else every pair is taken as apart, state unused).
template <bool GRID, bool INVERSE, bool CLASSIFY>
__attribute__((always_inline)) inline void film_only_loop(const PairAtoms &atoms, const NormalModel &model,
                                                          const int *__restrict pair_i, const int *__restrict pair_j,
                                                          int n, double *__restrict force_x, double *__restrict force_y,
                                                          double *__restrict force_z, double *__restrict film_force,
                                                          double *__restrict capacity, int *__restrict state)
{
  const Lubrication film_law = model.lubrication;
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  const double grid_reach = film_law.reach(1.0);    // with a grid the same for every R (lubrication.h)
  for (int c = 0; c < n; c++) {
    const PairGeometry g = pair_geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const double gap = g.r - g.radsum;
    double film = film_force_apart<GRID>(film_law, gap, g.film, g.m_e, g.u_n, dt, inv_dt);
    if (CLASSIFY) {
      // NormalModel::acts and contact_possible, selected.
      const double reach = GRID ? grid_reach : film_law.reach(g.film.value);
      const bool acts = gap < reach + std::fabs(g.u_n) * dt;
      const bool apart = !contact_possible(gap, g.u_n, dt);
      film = acts & apart ? film : 0.0;
      state[c] = acts ? (apart ? film_pair_apart : film_pair_general) : film_pair_idle;
    }
    const double fpair = g.rinv * film;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    film_force[c] = film;
    capacity[c] = film_capacity(g.m_e, g.u_n);
  }
}

}    // namespace lubricated
