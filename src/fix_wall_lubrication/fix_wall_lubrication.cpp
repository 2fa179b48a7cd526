/* ----------------------------------------------------------------------
   fix wall/lubrication (see doc/fix_wall_lubrication.rst)

   fix ID group wall/lubrication e_d [keyword value ...] wallstyle lo hi
     keywords as in pair_coeff of pair_style lubricated/springdashpot
     wallstyle = xplane, yplane or zplane; lo, hi = wall positions or NULL
------------------------------------------------------------------------- */

#include "fix_wall_lubrication.h"

#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
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

int FixWallLubrication::setmask()
{
  return (coeffs.wet() ? PRE_FORCE : 0) | POST_FORCE | MIN_POST_FORCE;
}

void FixWallLubrication::init()
{
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
  pair = dynamic_cast<PairLubricatedSpringDashpot *>(force->pair_match("lubricated/springdashpot", 1));
  contact_mass.init(STYLE, !pair);    // the pair style logs them where there is one
  // Point particles are refused; with a grid spacing the smallest spheres have the largest
  // eps_al (at most 1, as activation).
  const std::string problem = lub::validate_grid_for_radius(coeffs, smallest_sphere_radius(lmp, STYLE, groupbit));
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);
  films_pending = false;
}

// k = m (pi^2 + ln^2 e_d) / (N_c dt)^2 follows the time step when N_c is given.
void FixWallLubrication::reset_dt()
{
  model = lub::make_normal_model(coeffs, lub::Partner::wall, update->dt);
  tmodel = lub::make_tangential_model(coeffs, update->dt);
}

// A wet wall is computed before the pair style, its films applied after it (within the
// budget); a dry wall has no film and is computed after the pair style as it always was.
void FixWallLubrication::setup_pre_force(int /*vflag*/)
{
  if (update->whichflag == 1 && model.lubrication.active()) compute_walls(true);
}

void FixWallLubrication::pre_force(int /*vflag*/)
{
  if (model.lubrication.active()) compute_walls(true);
}

void FixWallLubrication::setup(int /*vflag*/)
{
  if (model.lubrication.active())
    apply_films();
  else
    compute_walls(false);
}

void FixWallLubrication::post_force(int /*vflag*/)
{
  if (model.lubrication.active())
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
  if (!model.lubrication.active()) return;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int sides = (has_lo ? 1 : 0) + (has_hi ? 1 : 0);
  const bool shear_film = tmodel.film_active();    // no bound on its share yet: 1
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      bound[i] +=
          sides * (shear_film ? 1.0 : lub::film_share_bound(model.lubrication, radius[i], rmass[i], update->dt));
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
  double **v = atom->v;
  double **f = atom->f;
  const double *radius = atom->radius;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const lub::Evaluation when = lub::evaluation_of(update->setupflag != 0, midpoint != nullptr);
  const bool tangential_on = tmodel.active();

  for (double &s : local_sums)
    s = 0.0;
  sums_reduced = false;
  films_pending = defer_films = defer_films && model.lubrication.active();
  shear_pending = defer_films && tmodel.film_active();
  if (defer_films) {
    film_force.assign(nlocal, 0.0);
    film_load.assign(nlocal, 0.0);
  }
  if (shear_pending) shear_film.assign(6 * static_cast<std::size_t>(nlocal), 0.0);
  const double kick_time =
      lub::film_kick_time(update->dt, when != lub::Evaluation::step, when == lub::Evaluation::midpoint_start);
  // Both walls on atom i of contact mass `mass`.
  auto walls_of_atom = [&](int i, double mass) __attribute__((always_inline))
  {
    const double r = radius[i];
    // side = +1: lo wall, normal along +axis; side = -1: hi wall, normal along -axis.
    for (int side = 1; side >= -1; side -= 2) {
      if (side == 1 ? !has_lo : !has_hi) continue;
      const double gap = side * (x[i][axis] - (side == 1 ? lo : hi)) - r;
      const double u_n = side * (midpoint && model.exact ? midpoint->step_velocity(i)[axis] : v[i][axis]);
      if (!model.acts(gap, r, u_n)) {
        if (history && history[i][(side == 1 ? 0 : HISTORY_PER_WALL) + 3] != 0.0)
          for (int k = 0; k < HISTORY_PER_WALL; k++)
            history[i][(side == 1 ? 0 : HISTORY_PER_WALL) + k] = 0.0;
        continue;
      }
      const lub::NormalForce fn = lub::normal_force(model, gap, r, mass, u_n, when);
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
      if (tangential_on) {
        double ft[3] = {0.0, 0.0, 0.0}, torque[3] = {0.0, 0.0, 0.0};
        // The shear film deferred with the normal one: its force and torque (shear, 6) and
        // share (shear[6]); the contact's share the larger of the two (film_budget.h).
        double shear[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        tangential(i, side, gap, u_n, fn.contact, mass, ft, torque, kick_time, shear_pending ? shear : nullptr);
        if (shear_pending) {
          film_load[i] += lub::contact_film_share(share, shear[6]);
          for (int d = 0; d < 6; d++)
            shear_film[6 * i + d] += shear[d];
        }
        for (int d = 0; d < 3; d++) {
          f[i][d] += ft[d];
          atom->torque[i][d] += torque[d];
          local_sums[1 + d] += ft[d];
        }
      }
    }
  };

  // m_e = m; the body's mass for an atom of a rigid body; an immovable atom is left alone.
  if (!contact_mass.active()) {
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit) walls_of_atom(i, rmass[i]);
    return;
  }
  // Atoms change index only where the lists are rebuilt (or a run starts).
  if (neighbor->ago == 0 || update->setupflag || static_cast<int>(inverse_mass.size()) < nlocal) {
    if (static_cast<int>(inverse_mass.size()) < nlocal) inverse_mass.resize(atom->nmax);
    contact_mass.fill(inverse_mass.data());
  }
  for (int i = 0; i < nlocal; i++)
    if ((mask[i] & groupbit) && inverse_mass[i] > 0.0) walls_of_atom(i, 1.0 / inverse_mass[i]);
}

// Tangential force and torque on i from the wall on this side (tangential.h, m_e = mass; the
// rolling resistance with the sphere's own inertia). shear (7 doubles, or nullptr): the shear
// film is left out of force and torque and returned there instead (force, torque, and its share
// of the film budget for this kick time, film_budget.h).
void FixWallLubrication::tangential(int i, int side, double gap, double u_n, double normal_force, double mass,
                                    double *force, double *torque, double kick_time, double *shear)
{
  const double r = atom->radius[i], m = atom->rmass[i];
  const double *v = atom->v[i], *w = atom->omega[i];
  lub::Vec3 n;
  (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = side;
  const lub::Vec3 omega{w[0], w[1], w[2]};
  const lub::Vec3 s =
      lub::tangential_part(lub::minus(lub::Vec3{v[0], v[1], v[2]}, lub::cross(lub::scaled(omega, r), n)), n);
  const double m_t = lub::tangential_mass_ratio * mass;

  lub::Vec3 f;
  if (history) {
    double *h = history[i] + (side == 1 ? 0 : HISTORY_PER_WALL);
    if (tmodel.contact_active() && lub::tangential_in_contact(gap)) {
      const double fraction = h[3] != 0.0 ? 1.0 : lub::first_contact_fraction(gap, u_n, tmodel.dt);
      lub::Vec3 delta{h[0], h[1], h[2]};
      f = lub::tangential_contact_force(tmodel, delta, n, s, m_t, normal_force, fraction);
      h[0] = delta.x, h[1] = delta.y, h[2] = delta.z, h[3] = 1.0;
    } else if (h[3] != 0.0) {
      h[0] = h[1] = h[2] = h[3] = 0.0;
    }
  }
  if (tmodel.film_active()) {
    const lub::Vec3 fs = lub::shear_film_force(tmodel, s, gap / r, model.lubrication.activation_for(r),
                                               model.lubrication.eps_saturation, model.lubrication.eps_release, r, m_t);
    if (shear) {
      const lub::Vec3 nxfs = lub::cross(n, fs);
      shear[0] = fs.x, shear[1] = fs.y, shear[2] = fs.z;
      shear[3] = -r * nxfs.x, shear[4] = -r * nxfs.y, shear[5] = -r * nxfs.z;
      shear[6] = lub::shear_film_share(lub::dot(fs, fs), lub::dot(s, s), m_t, kick_time);
    } else {
      f = lub::plus(f, fs);
    }
  }
  lub::Vec3 roll;
  if (tmodel.rolling_active() && gap < 0.0)
    roll = lub::rolling_torque(tmodel, n, omega, r, 0.4 * m * r * r, normal_force);
  const lub::Vec3 nxf = lub::cross(n, f);
  force[0] = f.x, force[1] = f.y, force[2] = f.z;
  torque[0] = -r * nxf.x + roll.x, torque[1] = -r * nxf.y + roll.y, torque[2] = -r * nxf.z + roll.z;
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
