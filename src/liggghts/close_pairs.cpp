// The close pairs of one LIGGGHTS pass, evaluated in one vectorised loop (close_pairs.h).
#include "liggghts/close_pairs.h"

#include "atom.h"
#include "contact_model_constants.h"
#include "force.h"
#include "pair_gran.h"
#include "update.h"

#include "liggghts/fix_lubricated_film_budget.h"
#include "lubricated/film_budget.h"

#include <cmath>

// x86-64-v3 (AVX2) and v4 (AVX-512) have the gathers the loop needs; elsewhere it runs scalar.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define CLOSE_PAIRS_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define CLOSE_PAIRS_CLONES
#endif

namespace lubricated {
namespace liggghts {

namespace {

// The model's tests and film of a step (normal_model.h: NormalModel::acts, contact_possible,
// film_force_apart) per pair, without branches: the results of pairs that do not need them
// are discarded by the state.
template <bool GRID> __attribute__((always_inline)) inline void
close_loop(const CloseAtoms &atoms, const NormalModel &model, int n, const int *__restrict pair_i,
           const int *__restrict pair_j, int *__restrict state, double *__restrict force_x, double *__restrict force_y,
           double *__restrict force_z, double *__restrict film, double *__restrict capacity)
{
  const double *__restrict x = atoms.x;
  const double *__restrict v = atoms.v;
  const double *__restrict radius = atoms.radius;
  const double *__restrict rmass = atoms.rmass;
  const Lubrication lub = model.lubrication;
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  const double grid_reach = lub.reach(1.0);    // with a grid the same for every R (lubrication.h)
  for (int c = 0; c < n; c++) {
    const int i = pair_i[c], j = pair_j[c];
    const double delx = x[3 * i] - x[3 * j], dely = x[3 * i + 1] - x[3 * j + 1], delz = x[3 * i + 2] - x[3 * j + 2];
    const double r = std::sqrt(delx * delx + dely * dely + delz * delz), rinv = 1.0 / r;
    const double en_x = delx * rinv, en_y = dely * rinv, en_z = delz * rinv;
    const double u_n =
        (v[3 * i] - v[3 * j]) * en_x + (v[3 * i + 1] - v[3 * j + 1]) * en_y + (v[3 * i + 2] - v[3 * j + 2]) * en_z;
    const double radi = radius[i], radj = radius[j];
    const double gap = r - (radi + radj);
    const FilmRadius radius_film = film_radius_pair(radi, radj);
    const double m_e = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
    const double reach = GRID ? grid_reach : lub.reach(radius_film.value);
    const bool acts = gap < reach + std::fabs(u_n) * dt;
    const bool apart = !contact_possible(gap, u_n, dt);
    const double force = film_force_apart<GRID>(lub, gap, radius_film, m_e, u_n, dt, inv_dt);
    const double along = acts & apart ? force : 0.0;
    state[c] = acts ? (apart ? close_film : close_general) : close_idle;
    film[c] = along;
    force_x[c] = along * en_x, force_y[c] = along * en_y, force_z[c] = along * en_z;
    capacity[c] = film_capacity(m_e, u_n);
  }
}

CLOSE_PAIRS_CLONES void close_loop_grid(const CloseAtoms &atoms, const NormalModel &model, int n, const int *pair_i,
                                        const int *pair_j, int *state, double *force_x, double *force_y,
                                        double *force_z, double *film, double *capacity)
{
  close_loop<true>(atoms, model, n, pair_i, pair_j, state, force_x, force_y, force_z, film, capacity);
}

CLOSE_PAIRS_CLONES void close_loop_fixed(const CloseAtoms &atoms, const NormalModel &model, int n, const int *pair_i,
                                         const int *pair_j, int *state, double *force_x, double *force_y,
                                         double *force_z, double *film, double *capacity)
{
  close_loop<false>(atoms, model, n, pair_i, pair_j, state, force_x, force_y, force_z, film, capacity);
}

}    // namespace

void ClosePairs::evaluate(const CloseAtoms &atoms, const NormalModel &model)
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
  evaluate({x[0], v[0], radius, rmass}, model);
  const int nlocal = atom->nlocal, newton_pair = lmp->force->newton_pair;
  const bool record = budget && budget->active();
  const double kick = film_kick_time(lmp->update->dt, false, false);
  // The film pairs' forces applied as LIGGGHTS applies a pair's (force_update(): its relax
  // factor), without a branch per pair (which pairs are idle or general follows no pattern): the
  // loop's force is zero for the others (close_loop). The general pairs listed for below.
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
    ngeneral += state[c] == close_general;
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
