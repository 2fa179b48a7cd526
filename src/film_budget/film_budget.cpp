/* ----------------------------------------------------------------------
   The many-body film budget of pair_style lubricated/springdashpot (film_budget.h)
------------------------------------------------------------------------- */

#include "film_budget.h"
#include "film_solve_step.h"

#include "lubricated/film_budget.h"

#include "atom.h"
#include "comm.h"
#include "fix.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
namespace lub = lubricated;

FilmBudget::FilmBudget(LAMMPS *lmp, AtomVectorComm &exchange) :
    Pointers(lmp), exchange(exchange), solve_step(new FilmSolveStep(lmp, exchange))
{
}

FilmBudget::~FilmBudget() = default;

void FilmBudget::init(bool limit_atom, bool wet_pairs, bool shear_films, const FilmSolveSettings &solve,
                      bool roll_films)
{
  limit_per_atom = limit_atom || solve.on;
  solve_on = solve.on;
  solve_step->configure(solve);
  solve_step->clear_counts();
  participants.clear();
  any_wet_participant = false;
  for (Fix *ifix : modify->get_fix_list()) {    // fix wall/lubrication and wall/lubrication/region
    auto participant = dynamic_cast<FilmBudgetParticipant *>(ifix);
    if (!participant) continue;
    participants.push_back(participant);
    any_wet_participant = any_wet_participant || participant->wet();
  }
  enabled = limit_per_atom && (wet_pairs || any_wet_participant);
  shear_records = enabled && (shear_films || roll_films);
  roll_records = enabled && roll_films;
  if (!enabled) scale_of_atom.clear();
  solve_step->start_run(participants);
}

void FilmBudget::grow_atoms()
{
  if (static_cast<int>(load_of_atom.size()) < atom->nlocal + atom->nghost) {
    load_of_atom.resize(atom->nmax);
    scale_of_atom.resize(atom->nmax);
  }
}

bool FilmBudget::bounds_due() const
{
  return neighbor->ago == 0 || update->setupflag || update->dt > bound_dt;
}

bool FilmBudget::may_be_active() const
{
  return enabled && (now || bounds_due());
}

void FilmBudget::begin_step(const NeighList *list, const TypeTables &tables)
{
  this->tables = tables;
  if (!enabled)
    now = false;
  else if (bounds_due())
    // The bounds grow with dt (lubricated/film_budget.h): those of a larger step hold for a
    // smaller one, so adaptive time stepping recomputes them only where dt grows past theirs.
    now = films_can_exceed_budget(list, tables);
  if (!now) return;
  // Loads start from the participants' films (computed in their pre_force) for owned atoms, 0
  // elsewhere.
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  grow_atoms();
  std::fill(load_of_atom.begin(), load_of_atom.begin() + nall, 0.0);
  for (auto participant : participants)
    participant->add_film_loads(load_of_atom.data(), nlocal);
  nrecord = 0;
}

// Each atom's sum of its pairs' bounds bound_of(i, j, rsq), its participants' added, over all
// ranks: whether any can exceed the budget.
template <class BoundOf> bool FilmBudget::sum_bounds_can_exceed(const NeighList *list, BoundOf &&bound_of)
{
  double **x = atom->x;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, newton_pair = force->newton_pair;
  double *bound = load_of_atom.data();
  std::fill(bound, bound + nall, 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
      const double b = bound_of(i, j, delx * delx + dely * dely + delz * delz);
      bound[i] += b;
      if (newton_pair || j < nlocal) bound[j] += b;
    }
  }
  for (auto participant : participants)
    participant->add_film_share_bounds(bound, nlocal);
  if (newton_pair) exchange.reverse(bound, 1);
  const int over = lub::any_load_can_exceed_budget(bound, nlocal) ? 1 : 0;
  int any = 0;
  MPI_Allreduce(&over, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

// Until the next neighbor list build a pair closes by at most the skin, so only the pairs of the
// list whose gap is below the film's reach plus the skin can have a film. Each atom's sum of
// those contacts' share bounds (and its participants') bounds its load: where no sum exceeds 1
// the budget would scale nothing and is skipped until the next build (or a larger time step).
// The bounds use the spheres' own masses, which no contact mass exceeds (contact_mass.h).
// First with one ceiling for every pair's share (lubricated/film_budget.h,
// pair_film_share_ceiling): where no atom's sum of those reaches 1, neither do the pairs' own
// bounds, whose logarithms are then spared.
bool FilmBudget::films_can_exceed_budget(const NeighList *list, const TypeTables &tables)
{
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  const double dt = update->dt, skin = neighbor->skin;
  bound_dt = dt;
  grow_atoms();

  double r_min = INFINITY, r_max = 0.0, m_min = INFINITY;
  for (int k = 0; k < nall; k++) {
    r_min = std::min(r_min, radius[k]), r_max = std::max(r_max, radius[k]);
    m_min = std::min(m_min, rmass[k]);
  }
  const int stride = tables.stride;
  double ceiling = 0.0;
  for (int a = 1; a < stride; a++)
    for (int b = 1; b < stride; b++) {
      const lub::ContactModel &model = tables.models[a * stride + b];
      ceiling = std::max(
          ceiling, lub::pair_film_share_ceiling(model.tangential, model.normal.lubrication, r_min, r_max, m_min, dt));
    }
  // The ceiling for every pair the types' largest film reach plus the skin allows.
  const bool ceiling_can_exceed = sum_bounds_can_exceed(list, [&](int i, int j, double rsq) {
    const double reach = reach_until_next_build(radius, type, tables.max_reach, stride, i, j, skin);
    return rsq < reach * reach ? ceiling : 0.0;
  });
  if (!ceiling_can_exceed) return false;
  return sum_bounds_can_exceed(list, [&](int i, int j, double rsq) {
    const lub::ContactModel &model = tables.models[type[i] * stride + type[j]];
    const lub::Lubrication &film = model.normal.lubrication;
    if (!film.active()) return 0.0;
    const lub::FilmRadius radius_ij = lub::film_radius_pair(radius[i], radius[j]);
    const double reach = radius[i] + radius[j] + film.reach(radius_ij.value) + skin;
    if (rsq >= reach * reach) return 0.0;
    // The contact's share is the larger of its normal and shear films' (lubricated/film_budget.h).
    const double m_e = lub::reduced_mass(rmass[i], rmass[j]);
    const double reduced_radius = radius[i] * radius[j] / (radius[i] + radius[j]);
    double tangential = lub::shear_film_share_bound(model.tangential, film, radius_ij.value, reduced_radius,
                                                    lub::tangential_mass_ratio * m_e, dt);
    if (model.tangential.roll_film_active())    // with the shear film's: both act on the spins
      tangential += lub::roll_film_share_bound(model.tangential, film, radius_ij.value, reduced_radius,
                                               lub::rolling_inertia(rmass[i], radius[i], rmass[j], radius[j]), dt);
    return std::max(lub::film_share_bound(film, radius_ij.value, m_e, dt), tangential);
  });
}

// A vector of exactly `size` elements (resize alone would at least double its capacity).
template <class T> static void resize_exactly(std::vector<T> &v, std::size_t size)
{
  v.reserve(size);
  v.resize(size);
}

// Room for `more` records (at most one per pair of the step's lists), with 1/8 spare: the
// count changes little from step to step, and doubling would hold twice the bed's films.
void FilmBudget::reserve_records(int more)
{
  if (nrecord + more <= static_cast<int>(record_i.size()) &&
      (!shear_records || record_shear.size() >= 3 * record_i.size()) &&
      (!roll_records || record_roll.size() >= 3 * record_i.size()))
    return;
  const std::size_t need = nrecord + more, size = need + need / 8;
  resize_exactly(record_i, size);
  resize_exactly(record_j, size);
  resize_exactly(record_force, size);
  if (shear_records) resize_exactly(record_shear, 3 * size);
  if (roll_records) resize_exactly(record_roll, 3 * size);
}

// Loads summed on the owners, scales sent to the ghosts, then every film whose atoms are over
// budget is scaled down by 1 / max(1, D_i, D_j) (lubricated/film_budget.h), or under `limit
// implicit` solved with the others of such atoms (film_solve_step.h).
void FilmBudget::finish(const double *inverse_mass, Tally *tally, const StepInputs *step)
{
  solve_step->clear_counts();
  if (!now) return;
  const int nlocal = atom->nlocal;
  if (force->newton_pair) exchange.reverse(load_of_atom.data(), 1);
  const double *load = load_of_atom.data();
  double *scale = scale_of_atom.data();
  // An atom no contact moves is not part of the state the budget protects: its load limits
  // nothing (its partners' own loads count their shares of these films).
  int over = 0;
  for (int i = 0; i < nlocal; i++) {
    scale[i] = (inverse_mass && inverse_mass[i] == 0.0) ? 1.0 : lub::film_scale_of_load(load[i]);
    over |= scale[i] < 1.0;
  }
  // Most steps of most beds leave every film whole: then no scales travel and nothing is redone.
  int any_over = 0;
  MPI_Allreduce(&over, &any_over, 1, MPI_INT, MPI_MAX, world);
  if (!any_over) return;
  exchange.forward(scale, 1);
  if (solve_on && step)
    solve_step->solve({record_i.data(), record_j.data(), record_force.data(),
                       shear_records ? record_shear.data() : nullptr, nrecord,
                       roll_records ? record_roll.data() : nullptr},
                      scale, tables, *step, tally);
  else if (shear_records)
    scale_films_and_shear(tally);
  else
    scale_films(tally);
}

// Per record, (s - 1) times the normal film along n.
void FilmBudget::scale_films(Tally *tally)
{
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const double *scale = scale_of_atom.data();
  double **x = atom->x, **f = atom->f;
  for (int r = 0; r < nrecord; r++) {
    const int i = record_i[r], j = record_j[r];
    const double s = std::min(scale[i], scale[j]);
    if (s == 1.0) continue;
    const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
    const double fpair = (s - 1.0) * record_force[r] / std::sqrt(delx * delx + dely * dely + delz * delz);
    f[i][0] += delx * fpair;
    f[i][1] += dely * fpair;
    f[i][2] += delz * fpair;
    if (newton_pair || j < nlocal) {
      f[j][0] -= delx * fpair;
      f[j][1] -= dely * fpair;
      f[j][2] -= delz * fpair;
    }
    if (tally) tally->tally_film_correction(i, j, fpair, delx, dely, delz);
  }
}

// With shear films: per record, (s - 1) times the normal film along n and the shear film at the
// contact points, with its torques -R_i n x f and -R_j n x f (lubricated/tangential.h), and the
// rolling film's torques.
void FilmBudget::scale_films_and_shear(Tally *tally)
{
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const double *scale = scale_of_atom.data(), *radius = atom->radius;
  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  for (int r = 0; r < nrecord; r++) {
    const int i = record_i[r], j = record_j[r];
    const double s = std::min(scale[i], scale[j]);
    if (s == 1.0) continue;
    const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
    const double rinv = 1.0 / std::sqrt(delx * delx + dely * dely + delz * delz);
    const double fpair = (s - 1.0) * record_force[r] * rinv;
    const double *shear = &record_shear[3 * r];
    const lub::Vec3 df{(s - 1.0) * shear[0], (s - 1.0) * shear[1], (s - 1.0) * shear[2]};
    const lub::Vec3 nxf = lub::cross(lub::Vec3{delx * rinv, dely * rinv, delz * rinv}, df);
    const double fx = delx * fpair + df.x, fy = dely * fpair + df.y, fz = delz * fpair + df.z;
    const double radi = radius[i], radj = radius[j];
    f[i][0] += fx;
    f[i][1] += fy;
    f[i][2] += fz;
    torque[i][0] -= radi * nxf.x;
    torque[i][1] -= radi * nxf.y;
    torque[i][2] -= radi * nxf.z;
    if (roll_records) {    // the rolling film's torque T on i, -T on j
      const double *roll = &record_roll[3 * r];
      for (int d = 0; d < 3; d++)
        torque[i][d] += (s - 1.0) * roll[d];
      if (newton_pair || j < nlocal)
        for (int d = 0; d < 3; d++)
          torque[j][d] -= (s - 1.0) * roll[d];
    }
    if (newton_pair || j < nlocal) {
      f[j][0] -= fx;
      f[j][1] -= fy;
      f[j][2] -= fz;
      torque[j][0] -= radj * nxf.x;
      torque[j][1] -= radj * nxf.y;
      torque[j][2] -= radj * nxf.z;
    }
    if (tally) tally->tally_film_correction_xyz(i, j, fx, fy, fz, delx, dely, delz);
  }
}

int FilmBudget::solve_iterations() const
{
  return solve_step->last_iterations();
}

int FilmBudget::solved_films() const
{
  return solve_step->last_solved_films();
}

lubricated::SolvedFilms FilmBudget::solved_now() const
{
  return solve_step->solved_at(update->ntimestep);
}

double FilmBudget::memory_usage() const
{
  return solve_step->memory_usage() + (record_i.capacity() + record_j.capacity()) * sizeof(int) +
         (load_of_atom.capacity() + scale_of_atom.capacity() + record_force.capacity() + record_shear.capacity() +
          record_roll.capacity()) *
             sizeof(double);
}
