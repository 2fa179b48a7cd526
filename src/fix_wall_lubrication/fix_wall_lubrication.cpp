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
#include "fix_step_velocity/fix_step_velocity.h"
#include "lubricated/check_setup.h"
#include "lubricated/film_budget.h"
#include "lubricated/film_cavitation.h"
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

#include <algorithm>

#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix wall/lubrication";

FixWallLubrication::FixWallLubrication(LAMMPS *lmp, int narg, char **arg) : FixLubricatedWall(lmp, narg, arg)
{
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

// A deferred wall film, scaled, in the outputs: the force on the group.
void FixWallLubrication::tally_film(int /*i*/, const lub::Vec3 &force, const lub::Vec3 & /*moment*/)
{
  local_sums[1] += force.x, local_sums[2] += force.y, local_sums[3] += force.z;
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

  clear_sums();
  films_pending = defer_films = defer_films && model.normal.lubrication.active();
  shear_pending = defer_films && model.tangential.film_active();
  clear_films();
  const double kick_time =
      lub::film_kick_time(update->dt, when != lub::Evaluation::step, when == lub::Evaluation::midpoint_start);

  // The wall frame now and a step ago. A step evaluation takes the wall's motion over the last
  // step, as the spheres' velocities are (the gap a step ago is then exactly h - u_n dt); a run's
  // first evaluation, with full-step velocities, its velocity now (lubricated/wall_geometry.h).
  const double dt = update->dt, t = wall_time();
  const lub::Vec3 shift = motion.displacement(t);
  const bool over_step = when == lub::Evaluation::step;
  const lub::Vec3 wall_velocity = over_step ? motion.step_velocity(t, dt) : motion.velocity(t);
  const lub::Vec3 shift_before =
      over_step ? motion.displacement(t - dt) : lub::minus(shift, lub::scaled(wall_velocity, dt));

  // Atom i (contact mass `mass`) at wall w, gap and normal at p, where the contact acts. Out of
  // line: most atoms are far from the walls, and their loop stays short.
  auto wall_contact = [&](int i, const lub::WallSurface &w, const lub::WallPoint &at, double u_n, double film_radius,
                          double mass, double load, double *h) __attribute__((noinline))
  {
    const double r = radius[i];
    record_sustained(i, at.gap, u_n, at.n);
    lub::ContactPoint p;
    p.gap = at.gap, p.u_n = u_n, p.reduced_mass = mass, p.film = lub::FilmRadius(film_radius);
    p.load = load;
    lub::HistorySlot slot;
    if (tangential_on) {
      // The sphere's motion relative to the wall frame gives the slip at the contact point.
      const lub::RelativeMotion rel =
          lub::relative_to_wall(lub::rigid_motion(w, motion, wall_velocity, shift), {v[i][0], v[i][1], v[i][2]},
                                {omega[i][0], omega[i][1], omega[i][2]}, r, at.n,
                                {x[i][0] - r * at.n.x, x[i][1] - r * at.n.y, x[i][2] - r * at.n.z});
      p.n = at.n;
      p.dv = rel.dv;
      p.omega_i = rel.omega;
      p.radius_i = r, p.reduced_radius = film_radius;    // R_f: the shear film's and rolling radius
      p.mass_i = rmass[i];                               // the sphere's own inertia, also in a rigid body
      if (h) slot = {h, h[3] != 0.0, !update->setupflag};
    }
    const lub::ContactForces c =
        tangential_on ? lub::contact_forces<true, lub::Partner::wall>(model, p, slot, when, shear_pending)
                      : lub::contact_forces<false, lub::Partner::wall>(model, p, slot, when);
    const lub::NormalForce &fn = c.normal;
    if (h) h[3] = slot.touched;
    const lub::Lubrication &film_law = model.normal.lubrication;
    const double film_n =
        fn.lubrication + lub::cavitation_relief(film_law.six_pi_mu, film_radius,
                                                std::max(at.gap, film_law.eps_saturation * film_radius), u_n,
                                                cavitation, fn.lubrication);
    double force = fn.contact + film_n;
    double share = 0.0;
    std::size_t film = 0;    // the atom's entry among the deferred films
    if (defer_films) {       // applied in post_force, within the atom's film budget
      force = fn.contact;
      film = film_entry(i);
      film_force[3 * film] += film_n * at.n.x;
      film_force[3 * film + 1] += film_n * at.n.y;
      film_force[3 * film + 2] += film_n * at.n.z;
      share = lub::film_share(film_n, mass, u_n, kick_time);
      if (!shear_pending) film_load[film] += share;
    }
    const double fn_xyz[3] = {force * at.n.x, force * at.n.y, force * at.n.z};
    for (int d = 0; d < 3; d++) {
      f[i][d] += fn_xyz[d];
      local_sums[1 + d] += fn_xyz[d];
    }
    local_sums[0] += fn.energy;
    if (!tangential_on) return;
    // The shear film deferred with the normal one (its force and torque); the contact's share
    // the larger of the two films' (film_budget.h).
    if (shear_pending) {
      film_load[film] += lub::contact_film_share(share, c.shear_share(kick_time));
      double *out = &shear_film[6 * film];
      out[0] += c.shear.x, out[1] += c.shear.y, out[2] += c.shear.z;
      out[3] += c.shear_torque_i.x, out[4] += c.shear_torque_i.y, out[5] += c.shear_torque_i.z;
    }
    f[i][0] += c.tangential.x, f[i][1] += c.tangential.y, f[i][2] += c.tangential.z;
    torque[i][0] += c.torque_i.x, torque[i][1] += c.torque_i.y, torque[i][2] += c.torque_i.z;
    local_sums[1] += c.tangential.x, local_sums[2] += c.tangential.y, local_sums[3] += c.tangential.z;
  };
  // Every wall on atom i of contact mass `mass`.
  auto walls_of_atom = [&](int i, double mass) __attribute__((always_inline))
  {
    const double r = radius[i];
    const double *v_step = midpoint && model.normal.exact ? midpoint->step_velocity(i) : v[i];
    for (std::size_t k = 0; k < walls.size(); k++) {
      const lub::WallSurface &w = walls[k];
      const lub::WallPoint at = lub::wall_point(w, x[i], r, shift);
      const double u_n = lub::normal_step_velocity(w, at, x[i], v_step, r, shift_before, wall_velocity, dt);
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
    }
  };

  // Plane walls: most atoms are far from them. walls_of_atom's own test, on the wall's axis
  // alone, leaves out the atoms that no wall acts on and that hold no elongation to forget.
  constexpr int max_planes = 6;
  struct Plane {
    int axis, slot;
    double side, position, shift, velocity, load_reach;
  } planes[max_planes];
  bool planes_only = walls.size() <= max_planes;
  for (std::size_t k = 0; k < walls.size() && planes_only; k++) {
    const lub::WallSurface &w = walls[k];
    planes_only = !w.cylinder;
    const double s[3] = {shift.x, shift.y, shift.z}, u[3] = {wall_velocity.x, wall_velocity.y, wall_velocity.z};
    // How far gravity may move an atom towards the plane over a step, beyond |u_n| dt.
    double load_reach = 0.0;
    for (const Gravity &g : gravity)
      load_reach += std::fabs(g.acceleration[w.axis]) * dt * dt;
    planes[k] = {w.axis,    static_cast<int>(k), static_cast<double>(w.side), w.position, s[w.axis],
                 u[w.axis], load_reach};
  }
  const int nplanes = planes_only ? static_cast<int>(walls.size()) : 0;

  // m_e = m; the body's mass for an atom of a rigid body; an immovable atom is left alone.
  const bool by_inverse = contact_mass.active();
  if (by_inverse) {
    // Atoms change index only where the lists are rebuilt (or a run starts).
    if (neighbor->ago == 0 || update->setupflag || static_cast<int>(inverse_mass.size()) < nlocal) {
      if (static_cast<int>(inverse_mass.size()) < nlocal) inverse_mass.resize(atom->nmax);
      contact_mass.fill(inverse_mass.data());
    }
  }
  auto evaluate_atom = [&](int i) __attribute__((always_inline))
  {
    if (!(mask[i] & groupbit)) return;
    if (!by_inverse)
      walls_of_atom(i, rmass[i]);
    else if (inverse_mass[i] > 0.0)
      walls_of_atom(i, 1.0 / inverse_mass[i]);
  };
  // Other walls: every atom of the group.
  if (!planes_only || nlocal == 0) {
    for (int i = 0; i < nlocal; i++)
      evaluate_atom(i);
    warn_behind();
    return;
  }
  // Planes: per chunk of atoms, a loop without branches (vectorised) marks those a plane may
  // act on (as lubricated::wall_point, normal_step_velocity and NormalModel::acts, to
  // round-off) or that hold an elongation at it; then only those are evaluated. The velocities
  // are v, or the midpoint integrator's step velocities, as blocks of rows of width vw.
  constexpr int chunk = 256;
  double near[chunk];
  int listed[chunk];
  const bool midpoint_velocity = midpoint && model.normal.exact;
  const double *__restrict x_all = x[0];
  const double *__restrict v_all = midpoint_velocity ? midpoint->step_velocities() : v[0];
  const int vw = midpoint_velocity ? FixNVESphereMidpoint::step_velocity_stride() : 3;
  const double *held = history ? history[0] : nullptr;
  const lub::NormalModel &normal = model.normal;
  const double step_dt = normal.exact ? normal.step.dt : 0.0;
  const bool film_on = normal.lubrication.active(), grid_film = normal.lubrication.grid_spacing > 0.0;
  const double grid_reach = film_on && grid_film ? normal.lubrication.reach(1.0) : 0.0;
  const double eps_reach = film_on && !grid_film ? normal.lubrication.eps_activation : 0.0;
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
        near[c] = acts ? 1.0 : near[c];
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
      evaluate_atom(listed[k]);
  }
  warn_behind();
}
