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
  virial_global_flag = virial_peratom_flag = 1;    // in the virial on request: fix_modify virial yes
  thermo_virial = 0;
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
  solved_step = -1;    // a film solve's increments belong to the step that took them
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
  if (affine_flow && !domain->deform_flag)
    error->all(FLERR,
               "{}: flow affine needs a deforming box (fix deform, e.g. xy erate with remap v): the affine "
               "velocity is that of the box's deformation",
               STYLE);
  if (history) lay_out_tail(history_begun ? history_dt : update->dt);    // kept once the history has begun
  if (history && !stiff_warned) warn_stiff_history();
  step_velocity = dynamic_cast<FixStepVelocity *>(modify->get_fix_by_id(FixStepVelocity::ID));
  if (solves_acceleration() || rotation) check_last_force_fix();
}

// Beyond beta dt / (m + m_a + m_h) = 1 the drag is capped (post_force) but the history force
// is not: it is no longer balanced by the drag and overshoots (a sphere the drag stopped
// moves on, well above the closed form). Stokes' beta at rest,
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
                 "{} with added_mass, history or rotation must be the last fix that adds forces: define fix {} "
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
  double w_hi[3], lamda[3];
  if (domain->triclinic) domain->x2lamda(const_cast<double *>(x), lamda);    // the bins lie along the box edges
  for (int d = 0; d < 3; d++) {
    const int n = nbins[d];
    const double s = (domain->triclinic ? lamda[d] : (x[d] - domain->boxlo[d]) / domain->prd[d]) * n - 0.5;
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
