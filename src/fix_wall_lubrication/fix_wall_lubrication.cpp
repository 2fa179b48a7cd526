/* ----------------------------------------------------------------------
   fix wall/lubrication (see doc/fix_wall_lubrication.rst)

   fix ID group wall/lubrication e_d [keyword value ...] wallstyle lo hi
     keywords as in pair_coeff of pair_style lubricated/springdashpot
     wallstyle = xplane, yplane or zplane; lo, hi = wall positions or NULL
------------------------------------------------------------------------- */

#include "fix_wall_lubrication.h"

#include "unit_style/unit_style.h"

#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_step_velocity/fix_step_velocity.h"
#include "lubricated/check_setup.h"
#include "lubricated/film_budget.h"
#include "pair_lubricated_springdashpot/pair_lubricated_springdashpot.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix wall/lubrication";

FixWallLubrication::FixWallLubrication(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg), contact_mass(lmp)
{
  ContactMass::watch_setforce(lmp);    // again after a `clear`
  require_supported_units(lmp, STYLE);
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "{} requires atom_style sphere (per-atom radius and rmass)", STYLE);

  // Coefficient words run up to the wall style, exactly as in pair_coeff.
  int iwall = 3;
  while (iwall < narg && strcmp(arg[iwall], "xplane") != 0 && strcmp(arg[iwall], "yplane") != 0 &&
         strcmp(arg[iwall], "zplane") != 0)
    iwall++;
  std::vector<std::string> words(arg + 3, arg + iwall);
  const std::string problem = lub::parse_coefficients(words, 0, coeffs);
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);
  if (iwall == narg) error->all(FLERR, "{}: missing wall style (expected xplane, yplane or zplane lo hi)", STYLE);
  if (iwall + 3 > narg) error->all(FLERR, "{}: {} needs lo and hi positions", STYLE, arg[iwall]);
  if (iwall + 3 < narg) error->all(FLERR, "{}: unknown keyword '{}' after the wall positions", STYLE, arg[iwall + 3]);

  axis = arg[iwall][0] - 'x';
  if (axis == 2 && domain->dimension == 2) error->all(FLERR, "{}: zplane is not allowed in 2d", STYLE);
  if (strcmp(arg[iwall + 1], "NULL") != 0) {
    has_lo = true;
    lo = utils::numeric(FLERR, arg[iwall + 1], false, lmp);
  }
  if (strcmp(arg[iwall + 2], "NULL") != 0) {
    has_hi = true;
    hi = utils::numeric(FLERR, arg[iwall + 2], false, lmp);
  }
  if (!has_lo && !has_hi) error->all(FLERR, "{}: both walls are NULL", STYLE);
  if (has_lo && has_hi && lo >= hi) error->all(FLERR, "{}: lo = {} must be below hi = {}", STYLE, lo, hi);

  scalar_flag = 1;    // elastic energy stored in the wall springs
  vector_flag = 1;    // total force of the walls on the group
  size_vector = 3;
  global_freq = 1;
  extscalar = 1;
  extvector = 1;
  energy_global_flag = 1;
  dynamic_group_allow = 1;

  if (coeffs.tangential() && !(atom->omega_flag && atom->torque_flag))
    error->all(FLERR,
               "{} with friction, rolling or shearfilm requires per-atom omega and torque "
               "(atom_style sphere)",
               STYLE);
  if (keeps_history()) {
    restart_peratom = 1;
    create_attribute = 1;
    maxexchange = HISTORY_SIZE;
    grow_arrays(atom->nmax);
    for (int i = 0; i < atom->nmax; i++)
      set_arrays(i);
    atom->add_callback(Atom::GROW);
    atom->add_callback(Atom::RESTART);
  }
}

FixWallLubrication::~FixWallLubrication()
{
  if (keeps_history()) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  memory->destroy(history);
}

// The shared fix that lets a run's set-up continue the last run (created here, after this fix
// is in place, when no pair style made it).
void FixWallLubrication::post_constructor()
{
  FixStepVelocity::find_or_create(lmp);
}

int FixWallLubrication::setmask()
{
  return (coeffs.wet() ? PRE_FORCE : 0) | POST_FORCE | MIN_POST_FORCE;
}

void FixWallLubrication::init()
{
  lub::settle_contact_time(coeffs, update->dt);
  const lub::SetupCheck check = lub::check_setup(coeffs, lub::Partner::wall, update->dt);
  if (!check.error.empty()) error->all(FLERR, "{}: {}", STYLE, check.error);
  if (comm->me == 0) {
    utils::logmesg(lmp, "{}: {}\n", STYLE, check.description);
    if (!check.tangential.empty()) utils::logmesg(lmp, "{}: {}\n", STYLE, check.tangential);
    for (const std::string &w : check.warnings)
      error->warning(FLERR, "{}: {}", STYLE, w);
  }
  reset_dt();
  // Under fix nve/sphere/midpoint the step-exact integration uses the velocity over the
  // last step, which that fix provides (see pair_style lubricated/springdashpot).
  midpoint = nullptr;
  for (auto &ifix : modify->get_fix_by_style("^nve/sphere/midpoint$"))
    midpoint = dynamic_cast<FixNVESphereMidpoint *>(ifix);
  step_velocity = midpoint ? nullptr : dynamic_cast<FixStepVelocity *>(modify->get_fix_by_id(FixStepVelocity::ID));
  pair = dynamic_cast<PairLubricatedSpringDashpot *>(force->pair_match("lubricated/springdashpot", 1));
  contact_mass.init(STYLE, !pair);    // the pair style logs them where there is one
  // Point particles are refused; with a grid spacing the smallest spheres have the largest
  // eps_al (at most 1, as activation).
  const std::string problem = lub::validate_grid_for_radius(coeffs, smallest_sphere_radius(lmp, STYLE, groupbit));
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);
  films_pending = false;
}

// A new time step: the per-step constants follow it; k and c stay (t_c settled at the first run,
// lubricated/coefficients.h settle_contact_time).
void FixWallLubrication::reset_dt()
{
  model = lub::make_contact_model(coeffs, lub::Partner::wall, update->dt, &model);
}

// A wet wall is computed before the pair style, its films applied after it (within the
// budget); a dry wall has no film and is computed after the pair style as it always was.
void FixWallLubrication::setup_pre_force(int /*vflag*/)
{
  if (update->whichflag == 1 && model.normal.lubrication.active()) compute_walls(true);
}

void FixWallLubrication::pre_force(int /*vflag*/)
{
  if (model.normal.lubrication.active()) compute_walls(true);
}

void FixWallLubrication::setup(int /*vflag*/)
{
  if (model.normal.lubrication.active())
    apply_films();
  else
    compute_walls(false);
}

void FixWallLubrication::post_force(int /*vflag*/)
{
  if (model.normal.lubrication.active())
    apply_films();
  else
    compute_walls(false);
}

// Minimisation: the walls in one go, films as each contact's own cap leaves them.
void FixWallLubrication::min_setup(int /*vflag*/)
{
  compute_walls(false);
}

void FixWallLubrication::min_post_force(int /*vflag*/)
{
  compute_walls(false);
}

void FixWallLubrication::add_film_loads(double *load, int nlocal) const
{
  if (!films_pending) return;
  for (int i = 0; i < nlocal; i++)
    load[i] += film_load[i];
}

// Every atom of the group counts as near each wet wall: the bound of a wall contact is small
// (m_e = m) and the test runs once per neighbor list build.
void FixWallLubrication::add_film_share_bounds(double *bound, int nlocal) const
{
  if (!model.normal.lubrication.active()) return;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int sides = (has_lo ? 1 : 0) + (has_hi ? 1 : 0);
  const bool shear_film = model.tangential.film_active();    // no bound on its share yet: 1
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      bound[i] +=
          sides * (shear_film ? 1.0 : lub::film_share_bound(model.normal.lubrication, radius[i], rmass[i], update->dt));
}

// The deferred wall films, scaled by the atoms' film budget: the pair style's where it keeps
// one (its loads include these walls), this fix's own without a lubricated pair style, none
// under `limit pair`.
void FixWallLubrication::apply_films()
{
  if (!films_pending) return;
  films_pending = false;
  double **f = atom->f;
  const int nlocal = atom->nlocal;
  const bool by_pair = pair && pair->keeps_film_budget();
  const bool own = !pair;
  const double *shear = shear_pending ? shear_film.data() : nullptr;
  double **torque = atom->torque;
  for (int i = 0; i < nlocal; i++) {
    const double *fs = shear ? shear + 6 * i : nullptr;
    if (film_force[i] == 0.0 && !(fs && (fs[0] != 0.0 || fs[1] != 0.0 || fs[2] != 0.0))) continue;
    const double scale = by_pair ? pair->film_scale(i) : own ? lub::film_scale_of_load(film_load[i]) : 1.0;
    const double force = scale * film_force[i];
    f[i][axis] += force;
    local_sums[1 + axis] += force;
    if (fs) {
      for (int d = 0; d < 3; d++) {
        f[i][d] += scale * fs[d];
        torque[i][d] += scale * fs[3 + d];
        local_sums[1 + d] += scale * fs[d];
      }
    }
  }
}

void FixWallLubrication::compute_walls(bool defer_films)
{
  double **x = atom->x;
  // A set-up that continues the last run evaluates as its last step did, with its velocities
  // (fix_step_velocity.h); not with rigid bodies or immovable atoms.
  const bool continued = step_velocity && step_velocity->continues() && !contact_mass.active();
  double **v = continued ? step_velocity->velocity() : atom->v;
  double **omega = continued ? step_velocity->spin() : atom->omega;
  double **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const lub::Evaluation when =
      continued ? lub::Evaluation::step : lub::evaluation_of(update->setupflag != 0, midpoint != nullptr);
  const bool tangential_on = model.tangential.active();

  for (double &s : local_sums)
    s = 0.0;
  sums_reduced = false;
  films_pending = defer_films = defer_films && model.normal.lubrication.active();
  shear_pending = defer_films && model.tangential.film_active();
  if (defer_films) {
    film_force.assign(nlocal, 0.0);
    film_load.assign(nlocal, 0.0);
  }
  if (shear_pending) shear_film.assign(6 * static_cast<std::size_t>(nlocal), 0.0);
  const double kick_time =
      lub::film_kick_time(update->dt, when != lub::Evaluation::step, when == lub::Evaluation::midpoint_start);
  // Atom i (contact mass `mass`) at the wall of this side (+1: lo wall, normal along +axis; -1:
  // hi wall, normal along -axis), where the contact acts. Out of line: most atoms are far from
  // the walls, and their loop stays short.
  auto wall_contact = [&](int i, int side, double gap, double u_n, double mass, double *h) __attribute__((noinline))
  {
    const double r = radius[i];
    lub::ContactPoint p;
    p.gap = gap, p.u_n = u_n, p.reduced_mass = mass, p.film = lub::FilmRadius(r);
    lub::HistorySlot slot;
    if (tangential_on) {
      (axis == 0 ? p.n.x : axis == 1 ? p.n.y : p.n.z) = side;
      p.dv = {v[i][0], v[i][1], v[i][2]};
      p.omega_i = {omega[i][0], omega[i][1], omega[i][2]};
      p.radius_i = r, p.reduced_radius = r;
      p.mass_i = rmass[i];    // the sphere's own inertia, also in a rigid body
      if (h) slot = {h, h[3] != 0.0, !update->setupflag};
    }
    const lub::ContactForces c =
        tangential_on ? lub::contact_forces<true, lub::Partner::wall>(model, p, slot, when, shear_pending)
                      : lub::contact_forces<false, lub::Partner::wall>(model, p, slot, when);
    const lub::NormalForce &fn = c.normal;
    if (h) h[3] = slot.touched;
    double force = side * fn.total();
    double share = 0.0;
    if (defer_films) {    // applied in post_force, within the atom's film budget
      force = side * fn.contact;
      film_force[i] += side * fn.lubrication;
      share = lub::film_share(fn.lubrication, mass, u_n, kick_time);
      if (!shear_pending) film_load[i] += share;
    }
    f[i][axis] += force;
    local_sums[0] += fn.energy;
    local_sums[1 + axis] += force;
    if (!tangential_on) return;
    // The shear film deferred with the normal one (its force and torque); the contact's share
    // the larger of the two films' (film_budget.h).
    if (shear_pending) {
      film_load[i] += lub::contact_film_share(share, c.shear_share(kick_time));
      double *out = &shear_film[6 * i];
      out[0] += c.shear.x, out[1] += c.shear.y, out[2] += c.shear.z;
      out[3] += c.shear_torque_i.x, out[4] += c.shear_torque_i.y, out[5] += c.shear_torque_i.z;
    }
    f[i][0] += c.tangential.x, f[i][1] += c.tangential.y, f[i][2] += c.tangential.z;
    torque[i][0] += c.torque_i.x, torque[i][1] += c.torque_i.y, torque[i][2] += c.torque_i.z;
    local_sums[1] += c.tangential.x, local_sums[2] += c.tangential.y, local_sums[3] += c.tangential.z;
  };
  // Both walls on atom i of contact mass `mass`.
  auto walls_of_atom = [&](int i, double mass) __attribute__((always_inline))
  {
    const double r = radius[i];
    for (int side = 1; side >= -1; side -= 2) {
      if (side == 1 ? !has_lo : !has_hi) continue;
      const double gap = side * (x[i][axis] - (side == 1 ? lo : hi)) - r;
      const double u_n = side * (midpoint && model.normal.exact ? midpoint->step_velocity(i)[axis] : v[i][axis]);
      // This wall's friction history of the atom (elongation x y z, touched); out of reach, forgotten.
      double *h = history ? history[i] + (side == 1 ? 0 : HISTORY_PER_WALL) : nullptr;
      // A centre behind the wall (a wall placed through or beyond the atoms) is not in contact:
      // the overlap would exceed a radius and launch the atom (warn_behind counts them).
      if (gap >= -r && model.normal.acts(gap, r, u_n))
        wall_contact(i, side, gap, u_n, mass, h);
      else if (h && h[3] != 0.0)
        for (int k = 0; k < HISTORY_PER_WALL; k++)
          h[k] = 0.0;
    }
  };

  // m_e = m; the body's mass for an atom of a rigid body; an immovable atom is left alone.
  if (!contact_mass.active()) {
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit) walls_of_atom(i, rmass[i]);
    warn_behind();
    return;
  }
  // Atoms change index only where the lists are rebuilt (or a run starts).
  if (neighbor->ago == 0 || update->setupflag || static_cast<int>(inverse_mass.size()) < nlocal) {
    if (static_cast<int>(inverse_mass.size()) < nlocal) inverse_mass.resize(atom->nmax);
    contact_mass.fill(inverse_mass.data());
  }
  for (int i = 0; i < nlocal; i++)
    if ((mask[i] & groupbit) && inverse_mass[i] > 0.0) walls_of_atom(i, 1.0 / inverse_mass[i]);
  warn_behind();
}

// Once per run set-up: atoms whose centres lie behind a wall are left alone by it.
void FixWallLubrication::warn_behind()
{
  if (!update->setupflag) return;
  bigint count = 0, total = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) count += (has_lo && atom->x[i][axis] < lo) + (has_hi && atom->x[i][axis] > hi);
  MPI_Allreduce(&count, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total > 0 && comm->me == 0)
    error->warning(FLERR,
                   "{}: {} atom(s) have their centre behind a wall (lo = {}, hi = {}); the wall leaves them alone",
                   STYLE, total, has_lo ? lub::detail::number(lo) : "NULL", has_hi ? lub::detail::number(hi) : "NULL");
}

void FixWallLubrication::grow_arrays(int nmax)
{
  memory->grow(history, nmax, HISTORY_SIZE, "wall/lubrication:history");
}

void FixWallLubrication::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < HISTORY_SIZE; k++)
    history[j][k] = history[i][k];
}

void FixWallLubrication::set_arrays(int i)
{
  for (int k = 0; k < HISTORY_SIZE; k++)
    history[i][k] = 0.0;
}

int FixWallLubrication::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < HISTORY_SIZE; k++)
    buf[k] = history[i][k];
  return HISTORY_SIZE;
}

int FixWallLubrication::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < HISTORY_SIZE; k++)
    history[nlocal][k] = buf[k];
  return HISTORY_SIZE;
}

int FixWallLubrication::pack_restart(int i, double *buf)
{
  buf[0] = HISTORY_SIZE + 1;
  for (int k = 0; k < HISTORY_SIZE; k++)
    buf[k + 1] = history[i][k];
  return HISTORY_SIZE + 1;
}

void FixWallLubrication::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  for (int k = 0; k < HISTORY_SIZE; k++)
    history[nlocal][k] = extra[nlocal][m + 1 + k];
}

int FixWallLubrication::size_restart(int /*i*/)
{
  return HISTORY_SIZE + 1;
}

int FixWallLubrication::maxsize_restart()
{
  return HISTORY_SIZE + 1;
}

double FixWallLubrication::memory_usage()
{
  return history ? static_cast<double>(atom->nmax) * HISTORY_SIZE * sizeof(double) : 0.0;
}

double FixWallLubrication::compute_scalar()
{
  if (!sums_reduced) {
    MPI_Allreduce(local_sums, global_sums, 4, MPI_DOUBLE, MPI_SUM, world);
    sums_reduced = true;
  }
  return global_sums[0];
}

double FixWallLubrication::compute_vector(int n)
{
  compute_scalar();
  return global_sums[1 + n];
}
