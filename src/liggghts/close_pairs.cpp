// The close pairs of one LIGGGHTS pass, evaluated in one vectorised loop (close_pairs.h).
#include "liggghts/close_pairs.h"

#include "atom.h"
#include "contact_model_constants.h"
#include "force.h"
#include "pair_gran.h"
#include "update.h"

#include "liggghts/fix_lubricated_film_budget.h"
#include "lubricated/contact.h"
#include "lubricated/film_budget.h"
#include "lubricated/film_only_loop.h"
#include "lubricated/vector_clones.h"

#include <cmath>

namespace lubricated {
namespace liggghts {

namespace {

// The kernel's film-only loop (lubricated/film_only_loop.h), sorting the pairs as it goes: the
// results of pairs that do not need them are discarded by the state.
LUBRICATED_VECTOR_CLONES void close_loop_grid(const PairAtoms &atoms, const NormalModel &model, int n,
                                              const int *pair_i, const int *pair_j, int *state, double *force_x,
                                              double *force_y, double *force_z, double *film, double *capacity)
{
  film_only_loop<true, false, true>(atoms, model, pair_i, pair_j, n, force_x, force_y, force_z, film, capacity, state);
}

LUBRICATED_VECTOR_CLONES void close_loop_fixed(const PairAtoms &atoms, const NormalModel &model, int n,
                                               const int *pair_i, const int *pair_j, int *state, double *force_x,
                                               double *force_y, double *force_z, double *film, double *capacity)
{
  film_only_loop<false, false, true>(atoms, model, pair_i, pair_j, n, force_x, force_y, force_z, film, capacity, state);
}

}    // namespace

void ClosePairs::evaluate(const PairAtoms &atoms, const NormalModel &model)
{
  const int n = size();
  for (std::vector<double> *values : {&force_x, &force_y, &force_z, &film, &capacity})
    values->resize(n);
  state.resize(n);
  auto loop = model.lubrication.grid_spacing > 0.0 ? close_loop_grid : close_loop_fixed;
  loop(atoms, model, n, i_.data(), j_.data(), state.data(), force_x.data(), force_y.data(), force_z.data(), film.data(),
       capacity.data());
}

void ClosePairs::apply(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *pair, const NormalModel &model,
                       FixLubricatedFilmBudget *budget)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  double **x = atom->x, **v = atom->v;
  double *f = atom->f[0];
  const double *radius = atom->radius, *rmass = atom->rmass;
  evaluate({x[0], v[0], radius, rmass, nullptr}, model);
  const int nlocal = atom->nlocal, newton_pair = lmp->force->newton_pair;
  const bool record = budget && budget->active();
  const double kick = evaluation_kind(lmp->update->dt, false, false, false).kick_time;    // a step (not a set-up)
  // The film pairs' forces applied as LIGGGHTS applies a pair's (force_update(): its relax
  // factor), without a branch per pair (which pairs are idle or general follows no pattern): the
  // loop's force is zero for the others (film_only_loop). The general pairs listed for below.
  const int n = size();
  if (static_cast<int>(general_.size()) < n) general_.resize(n);
  int *general = general_.data(), ngeneral = 0;
  for (int c = 0; c < n; c++) {
    const int a = i_[c], b = j_[c];
    const double relax_a = pair->relax(a);
    f[3 * a] += relax_a * force_x[c], f[3 * a + 1] += relax_a * force_y[c], f[3 * a + 2] += relax_a * force_z[c];
    if (newton_pair || b < nlocal) {
      const double relax_b = pair->relax(b);
      f[3 * b] -= relax_b * force_x[c], f[3 * b + 1] -= relax_b * force_y[c], f[3 * b + 2] -= relax_b * force_z[c];
    }
    general[ngeneral] = c;
    ngeneral += state[c] == film_pair_general;
  }
  if (record)
    for (int c = 0; c < n; c++) {
      if (film[c] == 0.0) continue;    // idle or general (or a film of zero): no record here
      const double on_i[3] = {force_x[c], force_y[c], force_z[c]};
      budget->add_film(i_[c], j_[c], on_i, film_share_of_capacity(film[c], capacity[c], kick));
    }
  // The few pairs where a contact may start within the step: as surfacesClose() evaluates one.
  for (int k = 0; k < ngeneral; k++) {
    const int c = general[k], a = i_[c], b = j_[c];
    const double del[3] = {x[a][0] - x[b][0], x[a][1] - x[b][1], x[a][2] - x[b][2]};
    const double r = std::sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]), r_inverse = 1.0 / r;
    const double en[3] = {del[0] * r_inverse, del[1] * r_inverse, del[2] * r_inverse};
    const double u_n = (v[a][0] - v[b][0]) * en[0] + (v[a][1] - v[b][1]) * en[1] + (v[a][2] - v[b][2]) * en[2];
    const double m_e = reduced_mass(rmass[a], rmass[b]);
    const NormalForce fn =
        normal_force(model, r - (radius[a] + radius[b]), film_radius_pair(radius[a], radius[b]), m_e, u_n);
    if (fn.total() == 0.0) continue;
    double on_i[3];
    for (int d = 0; d < 3; d++)
      on_i[d] = fn.total() * en[d];
    if (record && fn.lubrication != 0.0) {
      const double film_on_i[3] = {fn.lubrication * en[0], fn.lubrication * en[1], fn.lubrication * en[2]};
      budget->add_film(a, b, film_on_i, film_share_of_capacity(fn.lubrication, film_capacity(m_e, u_n), kick));
    }
    const double relax_a = pair->relax(a);
    for (int d = 0; d < 3; d++)
      f[3 * a + d] += relax_a * on_i[d];
    if (newton_pair || b < nlocal) {
      const double relax_b = pair->relax(b);
      for (int d = 0; d < 3; d++)
        f[3 * b + d] -= relax_b * on_i[d];
    }
  }
}

}    // namespace liggghts
}    // namespace lubricated
