/* ----------------------------------------------------------------------
   fix wall/lubrication (see doc/fix_wall_lubrication.rst)

   fix ID group wall/lubrication e_d [keyword value ...] wallstyle args [motion ...]
     keywords as in pair_coeff of pair_style lubricated/springdashpot
     wallstyle = xplane, yplane or zplane lo hi (NULL for none), or zcylinder R
     motion = translate vx vy vz, wiggle dim A T, shear dim v, side in|out (zcylinder)
   Parsing, per-atom history and restart: fix_wall_lubrication_setup.cpp.
------------------------------------------------------------------------- */

#include "fix_wall_lubrication.h"

#include "unit_style/unit_style.h"

#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "lubricated/film_budget.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix wall/lubrication";

FixWallLubrication::FixWallLubrication(LAMMPS *lmp, int narg, char **arg) : FixWallLubricationBase(lmp, narg, arg)
{
  adds_tangential_apart = true;
  ContactMass::watch_setforce(lmp);    // again after a `clear`
  require_supported_units(lmp, STYLE);
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "{} requires atom_style sphere (per-atom radius and rmass)", STYLE);

  // Coefficient words run up to the wall style, exactly as in pair_coeff.
  auto is_wall_style = [](const char *w) {
    return strcmp(w, "xplane") == 0 || strcmp(w, "yplane") == 0 || strcmp(w, "zplane") == 0 ||
           strcmp(w, "zcylinder") == 0;
  };
  int iwall = 3;
  while (iwall < narg && !is_wall_style(arg[iwall]))
    iwall++;
  std::vector<std::string> words(arg + 3, arg + iwall);
  const std::string problem = lub::parse_coefficients(words, 0, coeffs);
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);
  if (iwall == narg)
    error->all(FLERR, "{}: missing wall style (expected xplane, yplane or zplane lo hi, or zcylinder R)", STYLE);
  parse_walls(narg, arg, iwall);
  step_origin = update->ntimestep;
  motion_dt = update->dt;

  scalar_flag = 1;    // elastic energy stored in the wall springs
  vector_flag = 1;    // total force of the walls on the group
  size_vector = 3;
  global_freq = 1;
  extscalar = 1;
  extvector = 1;
  energy_global_flag = 1;
  dynamic_group_allow = 1;
  restart_global = 1;    // the motion's clock
  // A moving wall follows the steps since its definition: reset_timestep is refused (as for
  // fix move).
  time_depend = motion.moves() ? 1 : 0;

  if (coeffs.tangential() && !(atom->omega_flag && atom->torque_flag))
    error->all(FLERR,
               "{} with friction, rolling or shearfilm requires per-atom omega and torque "
               "(atom_style sphere)",
               STYLE);
  if (keeps_history()) {
    restart_peratom = 1;
    create_attribute = 1;
    maxexchange = history_size;
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

void FixWallLubrication::init()
{
  init_model(STYLE, "");    // and the motion's clock (reset_dt): a time step changed before this run counts from now
  // Point particles are refused; with a grid spacing the smallest film radii have the largest
  // eps_al (at most 1, as activation); spheres must fit inside a cylinder.
  check_sphere_sizes();
}

// A new time step: the per-step constants follow it; k and c stay (t_c settled at the first run,
// lubricated/coefficients.h settle_contact_time).
void FixWallLubrication::reset_dt()
{
  rebase_clock();
  model = lub::make_contact_model(coeffs, lub::Partner::wall, update->dt, &model);
}

// Every atom of the group counts as near each wet wall: the bound of a wall contact is small
// (m_e = m) and the test runs once per neighbor list build. A curved wall's film has R_f.
void FixWallLubrication::add_film_share_bounds(double *bound, int nlocal) const
{
  if (!model.normal.lubrication.active()) return;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const lub::Lubrication &film = model.normal.lubrication;
  const double dt = update->dt;
  // A wall contact: m_e = m_i, m_t = 2/7 m_i, the shear film's radius R_f (film_budget.h).
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      for (const lub::WallSurface &w : walls) {
        const double film_radius = w.film_radius(radius[i]);
        bound[i] += std::max(lub::film_share_bound(film, film_radius, rmass[i], dt),
                             lub::shear_film_share_bound(model.tangential, film, film_radius, film_radius,
                                                         lub::tangential_mass_ratio * rmass[i], dt));
      }
}

// A force on atom i in the outputs: the force of the walls on the group.
void FixWallLubrication::tally(int /*i*/, const lub::Vec3 &force, const lub::Vec3 & /*torque*/)
{
  local_sums[1] += force.x, local_sums[2] += force.y, local_sums[3] += force.z;
}

// The wall frame now and a step ago. A step evaluation takes the wall's motion over the last
// step, as the spheres' velocities are (the gap a step ago is then exactly h - u_n dt); a run's
// first evaluation, with full-step velocities, its velocity now (lubricated/wall_geometry.h).
void FixWallLubrication::place_walls()
{
  const double dt = update->dt, t = wall_time();
  frame.shift = motion.displacement(t);
  const bool over_step = pass.when == lub::Evaluation::step;
  frame.velocity = over_step ? motion.step_velocity(t, dt) : motion.velocity(t);
  frame.shift_before =
      over_step ? motion.displacement(t - dt) : lub::minus(frame.shift, lub::scaled(frame.velocity, dt));
}

void FixWallLubrication::find_contacts()
{
  place_walls();
  Plane planes[MAX_PLANES];
  const int nplanes = plane_walls(planes);
  // Other walls: every atom of the group.
  if (nplanes == 0 || atom->nlocal == 0) {
    for (int i = 0; i < atom->nlocal; i++)
      visit_atom(i, [this](int j, double mass) { walls_of_atom(j, mass); });
  } else {
    near_planes(planes, nplanes);
  }
  warn_behind();
}

// Plane walls: most atoms are far from them. walls_of_atom's own test, on the wall's axis
// alone, leaves out the atoms that no wall acts on and that hold no elongation to forget.
// Returns the number of walls, 0 where one is not a plane.
int FixWallLubrication::plane_walls(Plane *planes) const
{
  bool planes_only = walls.size() <= MAX_PLANES;
  const double dt = update->dt;
  const double s[3] = {frame.shift.x, frame.shift.y, frame.shift.z};
  const double u[3] = {frame.velocity.x, frame.velocity.y, frame.velocity.z};
  for (std::size_t k = 0; k < walls.size() && planes_only; k++) {
    const lub::WallSurface &w = walls[k];
    planes_only = !w.cylinder;
    // How far gravity may move an atom towards the plane over a step, beyond |u_n| dt.
    double load_reach = 0.0;
    for (const Gravity &g : gravity)
      load_reach += std::fabs(g.acceleration[w.axis]) * dt * dt;
    planes[k] = {w.axis,    static_cast<int>(k), static_cast<double>(w.side), w.position, s[w.axis],
                 u[w.axis], load_reach};
  }
  return planes_only ? static_cast<int>(walls.size()) : 0;
}

// Planes: per chunk of atoms, a loop without branches (vectorised) marks those a plane may
// act on (as lubricated::wall_point, normal_step_velocity and NormalModel::acts, to
// round-off) or that hold an elongation at it; then only those are evaluated. The velocities
// are v, or the midpoint integrator's step velocities, as blocks of rows of width vw.
void FixWallLubrication::near_planes(const Plane *planes, int nplanes)
{
  constexpr int chunk = 256;
  double near[chunk];
  int listed[chunk];
  const int nlocal = atom->nlocal;
  const double *radius = atom->radius;
  const bool midpoint_velocity = midpoint && model.normal.exact;
  const double *__restrict x_all = atom->x[0];
  const double *__restrict v_all = midpoint_velocity ? midpoint->step_velocities() : pass.v[0];
  const int vw = midpoint_velocity ? FixNVESphereMidpoint::step_velocity_stride() : 3;
  const double *held = history ? history[0] : nullptr;
  const lub::NormalModel &normal = model.normal;
  const double step_dt = normal.exact ? normal.step.dt : 0.0;
  const bool film_on = normal.lubrication.active(), grid_film = normal.lubrication.grid_spacing > 0.0;
  const double grid_reach = film_on && grid_film ? normal.lubrication.reach(1.0) : 0.0;
  const double eps_reach = film_on && !grid_film ? normal.lubrication.eps_activation : 0.0;
  const double dt = update->dt;
  for (int begin = 0; begin < nlocal; begin += chunk) {
    const int n = std::min(chunk, nlocal - begin);
    std::fill(near, near + n, 0.0);
    for (int k = 0; k < nplanes; k++) {
      const Plane w = planes[k];
      for (int c = 0; c < n; c++) {
        const int i = begin + c;
        const double r = radius[i];
        const double gap = w.side * (x_all[3 * i + w.axis] - w.position - w.shift) - r;
        const double u_n = w.side * (v_all[vw * i + w.axis] - w.velocity);
        const bool acts = (gap >= -r) & (gap < grid_reach + eps_reach * r + std::fabs(u_n) * step_dt + w.load_reach);
        // The centre went behind the plane over the last step, from an overlap (walls_of_atom).
        const double gap_before = gap - u_n * dt;
        const bool through = (gap < -r) & (gap_before >= -r) & (gap_before < 0.0);
        near[c] = acts | through ? 1.0 : near[c];
      }
      if (held)
        for (int c = 0; c < n; c++)
          near[c] = held[(begin + c) * history_size + w.slot * HISTORY_PER_WALL + 3] != 0.0 ? 1.0 : near[c];
    }
    int nlisted = 0;
    for (int c = 0; c < n; c++) {
      listed[nlisted] = begin + c;
      nlisted += near[c] != 0.0;
    }
    for (int k = 0; k < nlisted; k++)
      visit_atom(listed[k], [this](int j, double mass) { walls_of_atom(j, mass); });
  }
}

// Every wall on atom i of contact mass `mass`.
inline void FixWallLubrication::walls_of_atom(int i, double mass)
{
  double **x = atom->x;
  const double r = atom->radius[i];
  const double *v_step = midpoint && model.normal.exact ? midpoint->step_velocity(i) : pass.v[i];
  for (std::size_t k = 0; k < walls.size(); k++) {
    const lub::WallSurface &w = walls[k];
    const lub::WallPoint at = lub::wall_point(w, x[i], r, frame.shift);
    const double u_n =
        lub::normal_step_velocity(w, at, x[i], v_step, r, frame.shift_before, frame.velocity, update->dt);
    const double film_radius = w.film_radius(r);
    // This wall's friction history of the atom (elongation x y z, touched); out of reach, forgotten.
    double *h = history ? history[i] + k * HISTORY_PER_WALL : nullptr;
    // A centre behind the wall (a wall placed through or beyond the atoms) is not in contact:
    // the overlap would exceed a radius and launch the atom (warn_behind counts them).
    // Gravity on the atom along the normal, pressing it onto the wall where > 0.
    const double load = gravity_load(i, at.n);
    if (at.gap >= -r && model.normal.acts(at.gap, film_radius, u_n, load))
      wall_contact(i, w, at, u_n, film_radius, mass, load, h);
    else if (h && h[3] != 0.0)
      for (int m = 0; m < HISTORY_PER_WALL; m++)
        h[m] = 0.0;
    // Behind the wall now, in overlap with it a step ago: it went through (the overlap check).
    const double gap_before = at.gap - u_n * update->dt;
    if (at.gap < -r && gap_before >= -r && gap_before < 0.0 && !update->setupflag) check_overlap(i, at.gap, true);
  }
}

// Atom i (contact mass `mass`) at wall w, gap and normal at p, where the contact acts. Out of
// line: most atoms are far from the walls, and their loop stays short.
__attribute__((noinline)) void FixWallLubrication::wall_contact(int i, const lub::WallSurface &w,
                                                                const lub::WallPoint &at, double u_n,
                                                                double film_radius, double mass, double load, double *h)
{
  WallContact contact;
  contact.gap = at.gap, contact.u_n = u_n, contact.load = load, contact.n = at.n;
  contact.film = lub::FilmRadius(film_radius);
  contact.history = h;
  if (model.tangential.active()) {
    // The sphere's motion relative to the wall frame gives the slip at the contact point.
    const double *x = atom->x[i], *v = pass.v[i], *omega = pass.omega[i];
    const double r = atom->radius[i];
    const lub::RelativeMotion rel = lub::relative_to_wall(lub::rigid_motion(w, motion, frame.velocity, frame.shift),
                                                          {v[0], v[1], v[2]}, {omega[0], omega[1], omega[2]}, r, at.n,
                                                          {x[0] - r * at.n.x, x[1] - r * at.n.y, x[2] - r * at.n.z});
    contact.dv = rel.dv, contact.omega = rel.omega;
    contact.reduced_radius = film_radius;    // R_f: the shear film's and rolling radius
  }
  apply_contact(i, mass, contact);
}
