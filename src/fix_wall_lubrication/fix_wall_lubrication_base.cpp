/* ----------------------------------------------------------------------
   The wall fixes' shared part (fix_wall_lubrication_base.h)
------------------------------------------------------------------------- */

#include "fix_wall_lubrication_base.h"

#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_step_velocity/fix_step_velocity.h"
#include "lubricated/check_setup.h"
#include "film_budget/film_budget.h"
#include "lubricated/film_budget.h"
#include "plugin/run_steps.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "pair.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace lub = lubricated;

// The shared fix that lets a run's set-up continue the last run (created here, after this fix
// is in place, when no pair style made it).
void FixWallLubricationBase::post_constructor()
{
  FixStepVelocity::find_or_create(lmp);
}

int FixWallLubricationBase::setmask()
{
  return (coeffs.wet() ? PRE_FORCE : 0) | POST_FORCE | MIN_POST_FORCE;
}

void FixWallLubricationBase::parse_cavitation(const char *style, const char *value, bool &seen)
{
  if (seen) error->all(FLERR, "{}: cavitation given twice", style);
  seen = true;
  const bool none = strcmp(value, "none") == 0;    // the film as it is (the default)
  cavitation = none ? -1.0 : utils::numeric(FLERR, value, false, lmp);
  if (!none && !(cavitation >= 0.0 && std::isfinite(cavitation)))
    error->all(FLERR, "{}: cavitation dp_c = {} is out of range (allowed: none, or 0 <= dp_c, finite)", style, value);
}

void FixWallLubricationBase::init_model(const char *style, const std::string &what)
{
  lub::settle_contact_time(coeffs, update->dt, run_has_steps(update));
  const lub::SetupCheck check = lub::check_setup(coeffs, lub::Partner::wall, update->dt);
  if (!check.error.empty()) error->all(FLERR, "{}: {}", style, check.error);
  if (comm->me == 0) {
    utils::logmesg(lmp, "{}: {}{}\n", style, what, check.description);
    if (!check.tangential.empty()) utils::logmesg(lmp, "{}: {}\n", style, check.tangential);
    for (const std::string &w : check.warnings)
      error->warning(FLERR, "{}: {}", style, w);
  }
  reset_dt();
  // Under fix nve/sphere/midpoint the step-exact integration uses the velocity over the last
  // step, which that fix provides (see pair_style lubricated/springdashpot).
  midpoint = FixNVESphereMidpoint::in_use(lmp, style);
  step_velocity = midpoint ? nullptr : dynamic_cast<FixStepVelocity *>(modify->get_fix_by_id(FixStepVelocity::ID));
  auto *budget_owner = dynamic_cast<FilmBudgetOwner *>(force->pair_match("lubricated/springdashpot", 1));
  pair_budget = budget_owner ? &budget_owner->film_budget() : nullptr;
  contact_mass.init(style, !pair_budget);    // the pair style logs them where there is one
  films_pending = false;
  overlap_warned = overlap_deep_warned = false;
  find_gravity();
}

// Gravity presses a sphere onto a wall below it: the wall contact takes it as a steady load
// b = -g . n (n from the wall to the sphere), which the integrator adds on top of the contact.
// Other forces are not taken into account.
void FixWallLubricationBase::find_gravity()
{
  gravity.clear();
  if (!model.normal.exact) return;
  for (Fix *other : modify->get_fix_list()) {
    if (!utils::strmatch(other->style, "^gravity")) continue;
    int dim = 0;
    const auto *acceleration = static_cast<const double *>(other->extract("gvec", dim));
    if (acceleration && dim == 1) gravity.push_back({acceleration, other->groupbit});
  }
}

void FixWallLubricationBase::setup_pre_force(int /*vflag*/)
{
  if (update->whichflag == 1 && model.normal.lubrication.active()) compute_walls(true);
}

void FixWallLubricationBase::pre_force(int /*vflag*/)
{
  if (model.normal.lubrication.active()) compute_walls(true);
}

void FixWallLubricationBase::setup(int /*vflag*/)
{
  if (model.normal.lubrication.active())
    apply_films();
  else
    compute_walls(false);
}

void FixWallLubricationBase::post_force(int /*vflag*/)
{
  if (model.normal.lubrication.active())
    apply_films();
  else
    compute_walls(false);
}

// Minimisation: the walls in one go, films as each contact's own cap leaves them.
void FixWallLubricationBase::min_setup(int /*vflag*/)
{
  compute_walls(false);
}

void FixWallLubricationBase::min_post_force(int /*vflag*/)
{
  compute_walls(false);
}

// At the start of each evaluation: its outputs and its sustained contacts.
void FixWallLubricationBase::clear_sums()
{
  for (double &s : local_sums)
    s = 0.0;
  sums_reduced = false;
  sustained.clear();
}

double FixWallLubricationBase::compute_scalar()
{
  if (!sums_reduced) {
    MPI_Allreduce(local_sums, global_sums, 1 + size_vector, MPI_DOUBLE, MPI_SUM, world);
    sums_reduced = true;
  }
  return global_sums[0];
}

double FixWallLubricationBase::compute_vector(int n)
{
  compute_scalar();
  return global_sums[1 + n];
}

double FixWallLubricationBase::memory_usage()
{
  return film_atom.capacity() * sizeof(int) +
         (film_force.capacity() + film_load.capacity() + shear_film.capacity() + inverse_mass.capacity()) *
             sizeof(double) +
         film_link.capacity() * sizeof(lub::FilmLink) + (link_entry.capacity() + solved_link.capacity()) * sizeof(int) +
         entry_solved.capacity();
}

void FixWallLubricationBase::clear_films()
{
  film_atom.clear(), film_force.clear(), film_load.clear(), shear_film.clear();
  film_link.clear(), link_entry.clear(), solved_link.clear(), entry_solved.clear();
}

// The deferred films' entry of owned atom i: a new one unless i's walls came just before.
std::size_t FixWallLubricationBase::film_entry(int i)
{
  if (!film_atom.empty() && film_atom.back() == i) return film_atom.size() - 1;
  film_atom.push_back(i);
  film_force.insert(film_force.end(), 3, 0.0);
  film_load.push_back(0.0);
  if (shear_pending) shear_film.insert(shear_film.end(), 6, 0.0);
  return film_atom.size() - 1;
}

void FixWallLubricationBase::add_film_loads(double *load, int nlocal) const
{
  if (!films_pending) return;
  for (std::size_t e = 0; e < film_atom.size(); e++)
    if (film_atom[e] < nlocal) load[film_atom[e]] += film_load[e];
}

void FixWallLubricationBase::apply_films()
{
  if (!films_pending) return;
  films_pending = false;
  double **f = atom->f, **torque = atom->torque;
  const bool by_pair = pair_budget && pair_budget->kept();
  const bool own = !pair_budget;
  const double *shear = shear_pending ? shear_film.data() : nullptr;
  for (std::size_t e = 0; e < film_atom.size(); e++) {
    const int i = film_atom[e];
    const double *ff = &film_force[3 * e];
    const double *fs = shear ? shear + 6 * e : nullptr;
    const bool film = ff[0] != 0.0 || ff[1] != 0.0 || ff[2] != 0.0;
    if (!film && !(fs && (fs[0] != 0.0 || fs[1] != 0.0 || fs[2] != 0.0))) continue;
    const bool solved = !entry_solved.empty() && entry_solved[e];
    const double scale = solved    ? 1.0
                         : by_pair ? pair_budget->scale(i)
                         : own     ? lub::film_scale_of_load(film_load[e])
                                   : 1.0;
    lub::Vec3 force = lub::scaled({ff[0], ff[1], ff[2]}, scale), moment;
    if (fs) {
      force = lub::plus(force, lub::scaled({fs[0], fs[1], fs[2]}, scale));
      moment = lub::scaled({fs[3], fs[4], fs[5]}, scale);
      torque[i][0] += moment.x, torque[i][1] += moment.y, torque[i][2] += moment.z;
    }
    f[i][0] += force.x, f[i][1] += force.y, f[i][2] += force.z;
    tally(i, force, moment);
  }
}

// The links of the deferred films of owned atoms whose scale is below 1 (all of an atom's walls).
int FixWallLubricationBase::add_film_links(const double *scale, std::vector<lub::FilmLink> &links)
{
  solved_link.clear();
  if (!links_pending) return 0;
  for (std::size_t k = 0; k < film_link.size(); k++)
    if (scale[film_link[k].i] < 1.0) {
      links.push_back(film_link[k]);
      solved_link.push_back(static_cast<int>(k));
    }
  return static_cast<int>(solved_link.size());
}

// The solved films replace the whole entries of their atoms: the normal and shear films' force,
// and the torque (with the shear film).
void FixWallLubricationBase::take_solved_films(const lub::FilmLinkForce *solved, int count)
{
  entry_solved.assign(film_atom.size(), 0);
  for (int m = 0; m < count; m++) {
    const std::size_t e = link_entry[solved_link[m]];
    double *ff = &film_force[3 * e];
    double *fs = shear_pending ? &shear_film[6 * e] : nullptr;
    if (!entry_solved[e]) {
      entry_solved[e] = 1;
      std::fill(ff, ff + 3, 0.0);
      if (fs) std::fill(fs, fs + 6, 0.0);
    }
    const lub::FilmLinkForce &f = solved[m];
    ff[0] += f.force_i.x, ff[1] += f.force_i.y, ff[2] += f.force_i.z;
    if (fs) fs[3] += f.torque_i.x, fs[4] += f.torque_i.y, fs[5] += f.torque_i.z;
  }
}
