/* ----------------------------------------------------------------------
   fix fluid/drag (see doc/fix_fluid_drag.rst)

   fix ID group fluid/drag viscosity mu keyword value ... (keywords: fix_fluid_drag_args.cpp)
------------------------------------------------------------------------- */

#include "fix_fluid_drag.h"

#include "fix_step_velocity/fix_step_velocity.h"

#include "unit_style/unit_style.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"
#include "variable.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix fluid/drag";

FixFluidDrag::FixFluidDrag(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  require_supported_units(lmp, STYLE);
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "{} requires atom_style sphere (per-atom radius and rmass)", STYLE);

  parse(narg, arg);
  if (domain->triclinic) error->all(FLERR, "{} does not support triclinic boxes", STYLE);
  // phi is a volume fraction of spheres; a 2-d box has no volume to divide by.
  if (needs_fraction() && domain->dimension != 3) {
    const char *what = model.hindrance == lub::Hindrance::richardson_zaki ? "hindrance richardson-zaki"
                       : model.hindrance == lub::Hindrance::di_felice     ? "hindrance di-felice"
                                                                          : "superficial yes";
    error->all(FLERR,
               "{}: {} needs the solid volume fraction phi, which needs a 3-d simulation (dimension = {}; allowed: "
               "dimension 3); drag without hindrance and superficial works in 2-d",
               STYLE, what, domain->dimension);
  }
  for (const auto &w : added_mass_walls)
    if (domain->periodicity[w.axis])
      error->all(FLERR, "{}: wall {}plane in a periodic dimension (the box must be non-periodic in {})", STYLE,
                 "xyz"[w.axis], "xyz"[w.axis]);

  vector_flag = 1;    // total fluid force on the group (3), mean solid fraction of occupied bins
  size_vector = 4;
  global_freq = 1;
  extvector = 0;
  dynamic_group_allow = 1;
  bin_solid.assign(nbins[0] * nbins[1] * nbins[2], 0.0);
  local_sum.assign(bin_solid.size(), 0.0);
  if (stores_fraction()) restart_global = 1;    // the last phi, for a restart between multiples of every
  if (history) {
    dynamic_group_allow = 0;    // an atom's history is kept while it is in the group
    setup_history();
  }
}

FixFluidDrag::~FixFluidDrag()
{
  for (auto &p : atom_velocity)
    memory->destroy(p);
  for (auto &p : atom_acceleration)
    memory->destroy(p);
  for (auto &p : atom_vorticity)
    memory->destroy(p);
  if (history) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
    memory->destroy(history_state);
  }
}

int FixFluidDrag::setmask()
{
  return POST_FORCE | (history ? PRE_FORCE : 0);
}

bool FixFluidDrag::needs_fraction() const
{
  return model.hindrance != lub::Hindrance::none || superficial;
}

void FixFluidDrag::init()
{
  for (Component *set : {velocity, acceleration, vorticity})
    for (int d = 0; d < 3; d++) {
      Component &c = set[d];
      if (c.name.empty()) continue;
      const char *what = set == velocity ? "velocity" : (set == acceleration ? "acceleration" : "vorticity");
      c.ivar = input->variable->find(c.name.c_str());
      if (c.ivar < 0) error->all(FLERR, "{}: variable {} for the fluid {} does not exist", STYLE, c.name, what);
      if (input->variable->equalstyle(c.ivar))
        c.per_atom = false;
      else if (input->variable->atomstyle(c.ivar))
        c.per_atom = true;
      else
        error->all(FLERR, "{}: variable {} must be equal-style or atom-style", STYLE, c.name);
    }
  run_dt = update->dt;
  run_dt_warned = false;
  if (history) lay_out_tail(history_begun ? history_dt : update->dt);    // kept once the history has begun
  if (history && !stiff_warned) warn_stiff_history();
  step_velocity = dynamic_cast<FixStepVelocity *>(modify->get_fix_by_id(FixStepVelocity::ID));
  if (solves_acceleration()) check_last_force_fix();
  if (history && update->dt != history_dt && !dt_warned && comm->me == 0) {
    error->warning(FLERR,
                   "{}: the time step changed from {} to {}: the Basset window is re-weighted, its "
                   "exponential tail keeps the old step (approximate history)",
                   STYLE, history_dt, update->dt);
    dt_warned = true;
  }
}

// Beyond beta dt / (m + m_a + m_h) = 1 the drag is capped (post_force) but the history force
// is not: it is no longer balanced by the drag and overshoots (a sphere the drag stopped
// moves on; 30 % above the closed form at 6 relaxation times per step). Stokes' beta at rest,
// the smallest of the laws, so the warning is not given where the cap never acts.
void FixFluidDrag::warn_stiff_history()
{
  const double root = std::sqrt(update->dt);
  double worst = 0.0, all = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double diameter = 2.0 * atom->radius[i];
    const double mass = atom->rmass[i] + added_mass * model.density * lub::sphere_volume(atom->radius[i]) +
                        2.0 * lub::basset_coefficient(diameter, model.density, model.viscosity) * root;
    worst = std::max(worst, 3.0 * lub::pi * model.viscosity * diameter * update->dt / mass);
  }
  MPI_Allreduce(&worst, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  if (all > 1.0) {
    if (comm->me == 0)
      error->warning(FLERR,
                     "{}: history yes with beta dt / (m + m_a + m_h) = {:.3g} (allowed for an accurate history: "
                     "<= 1; beta = 3 pi mu_f d): the drag is capped there but the history force is not, and "
                     "overshoots; use a time step {:.3g} times smaller or more",
                     STYLE, all, all);
    stiff_warned = true;
  }
}

// The added mass and the history's current step are solved for with the total force, so no
// force may be added after this fix's post_force (LAMMPS calls them in the order defined).
void FixFluidDrag::check_last_force_fix()
{
  bool after = false;
  for (int i = 0; i < modify->nfix; i++) {
    if (modify->fix[i] == this) {
      after = true;
      continue;
    }
    if (after && (modify->fmask[i] & POST_FORCE))
      error->all(FLERR,
                 "{} with added_mass or history must be the last fix that adds forces: define fix {} "
                 "(style {}) before it",
                 STYLE, modify->fix[i]->id, modify->fix[i]->style);
  }
}

// Values of constants or variables: equal-style into value, atom-style into per_atom.
void FixFluidDrag::evaluate(Component *components, double **per_atom)
{
  bool any_per_atom = false, any_variable = false;
  for (int d = 0; d < 3; d++) {
    any_per_atom = any_per_atom || components[d].per_atom;
    any_variable = any_variable || !components[d].name.empty();
  }
  if (any_per_atom && atom->nmax > maxatom) {
    maxatom = atom->nmax;
    for (double **set : {atom_velocity, atom_acceleration, atom_vorticity})
      for (int d = 0; d < 3; d++) {
        memory->destroy(set[d]);
        memory->create(set[d], maxatom, "fluid/drag:per_atom");
      }
  }
  if (!any_variable) return;
  modify->clearstep_compute();
  for (int d = 0; d < 3; d++) {
    Component &c = components[d];
    if (c.name.empty()) continue;
    if (c.per_atom)
      input->variable->compute_atom(c.ivar, igroup, per_atom[d], 1, 0);
    else
      c.value = input->variable->compute_equal(c.ivar);
  }
  modify->addstep_compute(update->ntimestep + 1);
}

void FixFluidDrag::setup(int vflag)
{
  post_force(vflag);
}

// Bin centres sit at (k + 1/2) h; a sphere's volume goes to the (up to) 8 nearest centres
// with trilinear weights, and the solid fraction is read back the same way, which smooths
// the count noise of small bins. Periodic dimensions wrap, bounded ones clamp.
int FixFluidDrag::cloud_in_cell(const double *x, int *bins, double *weights) const
{
  int lo[3], hi[3];
  double w_hi[3];
  for (int d = 0; d < 3; d++) {
    const int n = nbins[d];
    const double s = (x[d] - domain->boxlo[d]) / domain->prd[d] * n - 0.5;
    int k = static_cast<int>(std::floor(s));
    double frac = s - k;
    if (n == 1) {
      lo[d] = hi[d] = 0, w_hi[d] = 0.0;
      continue;
    }
    if (domain->periodicity[d]) {
      lo[d] = ((k % n) + n) % n;
      hi[d] = (lo[d] + 1) % n;
    } else {
      if (k < 0) k = 0, frac = 0.0;
      if (k > n - 2) k = n - 2, frac = 1.0;
      lo[d] = k;
      hi[d] = k + 1;
    }
    w_hi[d] = frac < 0.0 ? 0.0 : (frac > 1.0 ? 1.0 : frac);
  }
  int count = 0;
  for (int cz = 0; cz < 2; cz++)
    for (int cy = 0; cy < 2; cy++)
      for (int cx = 0; cx < 2; cx++) {
        const double w =
            (cx ? w_hi[0] : 1.0 - w_hi[0]) * (cy ? w_hi[1] : 1.0 - w_hi[1]) * (cz ? w_hi[2] : 1.0 - w_hi[2]);
        if (w == 0.0) continue;
        const int ix = cx ? hi[0] : lo[0], iy = cy ? hi[1] : lo[1], iz = cz ? hi[2] : lo[2];
        bins[count] = (iz * nbins[1] + iy) * nbins[0] + ix;
        weights[count++] = w;
      }
  return count;
}

double FixFluidDrag::solid_fraction_at(const double *x) const
{
  int bins[8];
  double weights[8];
  const int n = cloud_in_cell(x, bins, weights);
  double phi = 0.0;
  for (int k = 0; k < n; k++)
    phi += weights[k] * bin_solid[bins[k]];
  return phi;
}

// Solid volume of the group's spheres per bin over the bin volume, summed over ranks.
void FixFluidDrag::update_solid_fraction()
{
  std::fill(local_sum.begin(), local_sum.end(), 0.0);
  const int *mask = atom->mask;
  int bins[8];
  double weights[8];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double volume = lub::sphere_volume(atom->radius[i]);
    const int n = cloud_in_cell(atom->x[i], bins, weights);
    for (int k = 0; k < n; k++)
      local_sum[bins[k]] += weights[k] * volume;
  }
  MPI_Allreduce(local_sum.data(), bin_solid.data(), (int)bin_solid.size(), MPI_DOUBLE, MPI_SUM, world);
  const double bin_volume = domain->prd[0] * domain->prd[1] * domain->prd[2] / bin_solid.size();    // 3-d only
  for (double &v : bin_solid)
    v /= bin_volume;
  last_fraction_step = update->ntimestep;
}

void FixFluidDrag::post_force(int /*vflag*/)
{
  const int nlocal = atom->nlocal;
  // At multiples of every (LAMMPS's convention), so that split runs and restarts see the
  // same phi as one run; in between, the last one, also from the last run or a restart file.
  if (needs_fraction() && (last_fraction_step < 0 || update->ntimestep % every == 0)) update_solid_fraction();

  // Fluid velocity and acceleration: constants, equal-style or atom-style variables.
  evaluate(velocity, atom_velocity);
  const bool inertia = fluid_inertia();
  if (inertia) evaluate(acceleration, atom_acceleration);
  if (magnus || saffman) evaluate(vorticity, atom_vorticity);

  // A set-up that continues the last run drags with the velocities of its last step, as that
  // step did (fix_step_velocity.h, kept where the pair style or a wall fix of this plugin is).
  const bool continued = step_velocity && step_velocity->continues();
  double **x = atom->x, **v = continued ? step_velocity->velocity() : atom->v, **f = atom->f;
  double **omega = continued ? step_velocity->spin() : atom->omega;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const double dt = update->dt;
  for (double &t : totals)
    t = 0.0;
  totals_reduced = false;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double voidage = needs_fraction() ? 1.0 - solid_fraction_at(x[i]) : 1.0;
    const double fluid_scale = superficial ? 1.0 / std::max(voidage, model.min_voidage) : 1.0;
    double slip[3], speed2 = 0.0;
    for (int d = 0; d < 3; d++) {
      const double u = velocity[d].per_atom ? atom_velocity[d][i] : velocity[d].value;
      slip[d] = u * fluid_scale - v[i][d];
      speed2 += slip[d] * slip[d];
    }
    const double diameter = 2.0 * radius[i];
    double beta = lub::drag_beta(model, diameter, std::sqrt(speed2), voidage);
    const double buoyant_volume = model.density * lub::sphere_volume(radius[i]);
    if (!inertia) {
      // Explicit relaxation is stable and exact in steady state while beta dt / m <= 1;
      // beyond, the drag removes the slip in one step and never reverses it.
      beta = std::min(beta, rmass[i] / dt);
      for (int d = 0; d < 3; d++) {
        const double force = beta * slip[d] - buoyant_volume * gravity[d];
        f[i][d] += force;
        totals[d] += force;
      }
      continue;
    }

    // Maxey-Riley-Gatignol (fluid_inertia.h): added mass m_a and the history's current step
    // m_h are solved for with the total force F, (m + m_a + m_h) a = F + (m_a + m_h) Du/Dt + H.
    double fluid_accel[3], lift[3] = {0.0, 0.0, 0.0}, known[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < 3; d++)
      fluid_accel[d] = fluid_scale * (acceleration[d].per_atom ? atom_acceleration[d][i] : acceleration[d].value);
    const double m_a = added_mass * buoyant_volume;
    double m_h = 0.0;
    if (history) {
      const double coefficient = lub::basset_coefficient(diameter, model.density, model.viscosity);
      if (finite_re) {    // Mei-Adrian: the kernel of this step's slip speed
        mei_adrian.weigh(lub::mei_adrian_rate(std::sqrt(speed2), diameter, model.viscosity / model.density), dt);
        m_h = basset.known_force(history_state[i], coefficient, dt, known, mei_adrian.window(), mei_adrian.tail());
      } else
        m_h = basset.known_force(history_state[i], coefficient, dt, known);
    }
    // Near walls the added mass grows, per axis, and its change brings forces of its own
    // (wall_added_mass.h), with the velocity relative to the fluid, -slip.
    double axis_mass[3] = {m_a, m_a, m_a}, wall_force[3] = {0.0, 0.0, 0.0};
    if (!added_mass_walls.empty()) {
      const lub::WallAddedMass near =
          lub::wall_added_mass(added_mass_walls.data(), static_cast<int>(added_mass_walls.size()), radius[i], x[i]);
      const double relative[3] = {-slip[0], -slip[1], -slip[2]};
      lub::wall_added_mass_force(near, m_a, relative, wall_force);
      for (int d = 0; d < 3; d++)
        axis_mass[d] = m_a * near.mass[d];
    }
    const double m_eff = rmass[i] + std::min(axis_mass[0], std::min(axis_mass[1], axis_mass[2])) + m_h;
    beta = std::min(beta, m_eff / dt);    // the cap above, for the mass that the drag accelerates
    if (magnus || saffman) {
      double curl[3], part[3];
      for (int d = 0; d < 3; d++)
        curl[d] = vorticity[d].per_atom ? atom_vorticity[d][i] : vorticity[d].value;
      if (magnus) {
        const double spin[3] = {omega[i][0] - 0.5 * curl[0], omega[i][1] - 0.5 * curl[1], omega[i][2] - 0.5 * curl[2]};
        lub::magnus_force(radius[i], model.density, spin, slip, part);
        for (int d = 0; d < 3; d++)
          lift[d] += part[d];
      }
      if (saffman) {
        lub::saffman_force(diameter, model.density, model.viscosity, slip, curl, part);
        for (int d = 0; d < 3; d++)
          lift[d] += part[d];
      }
    }
    const double undisturbed = pressure ? buoyant_volume : 0.0;
    double accel[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < 3; d++) {
      const double fluid =
          beta * slip[d] - buoyant_volume * gravity[d] + undisturbed * fluid_accel[d] + lift[d] + wall_force[d];
      if (!solves_acceleration()) {
        f[i][d] += fluid;
        totals[d] += fluid;
        continue;
      }
      accel[d] = (f[i][d] + fluid + known[d] + (axis_mass[d] + m_h) * fluid_accel[d]) / (rmass[i] + axis_mass[d] + m_h);
      const double total = rmass[i] * accel[d];
      totals[d] += total - f[i][d];
      f[i][d] = total;
    }
    // A set-up keeps the last step's evaluation, which the next step commits: it is the end
    // value of that step, whereas the set-up's forces need not be the step's (nve/sphere/midpoint
    // evaluates at the mid-step point X~, V~ and ignores them). Only an atom's first end value
    // comes from a set-up.
    if (history && !(update->setupflag && history_state[i][0] > 1.5)) {
      const double wdot[3] = {fluid_accel[0] - accel[0], fluid_accel[1] - accel[1], fluid_accel[2] - accel[2]};
      lub::BassetHistory::store(history_state[i], wdot);
    }
  }
}

double FixFluidDrag::compute_vector(int n)
{
  if (!totals_reduced) {
    MPI_Allreduce(totals, totals_all, 3, MPI_DOUBLE, MPI_SUM, world);
    double occupied = 0.0, count = 0.0;
    for (double phi : bin_solid)
      if (phi > 0.0) occupied += phi, count += 1.0;
    totals_all[3] = count > 0.0 ? occupied / count : 0.0;
    totals_reduced = true;
  }
  return totals_all[n];
}

double FixFluidDrag::memory_usage()
{
  return 9.0 * maxatom * sizeof(double) + 2.0 * bin_solid.size() * sizeof(double) +
         (history ? (double)atom->nmax * basset.size() * sizeof(double) : 0.0);
}
