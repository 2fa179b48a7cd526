/* ----------------------------------------------------------------------
   fix fluid/drag (see doc/fix_fluid_drag.rst)

   fix ID group fluid/drag viscosity mu keyword value ...
     density rho_f | law stokes|schiller-naumann | hindrance none|richardson-zaki n|di-felice
     velocity ux uy uz (numbers or v_name) | superficial yes|no | buoyancy gx gy gz
     bins nx ny nz | every N
------------------------------------------------------------------------- */

#include "fix_fluid_drag.h"

#include "fix_step_velocity/fix_step_velocity.h"

#include "unit_style/unit_style.h"

#include "atom.h"
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

  bool have_viscosity = false;
  auto need = [&](int iarg, int n) {
    if (iarg + n >= narg) error->all(FLERR, "{}: missing value(s) for keyword {}", STYLE, arg[iarg]);
  };
  auto number = [&](int iarg) { return utils::numeric(FLERR, arg[iarg], false, lmp); };
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "viscosity") {
      need(iarg, 1);
      model.viscosity = number(iarg + 1);
      if (!(model.viscosity > 0.0))
        error->all(FLERR, "{}: viscosity = {} is out of range (allowed: mu_f > 0)", STYLE, arg[iarg + 1]);
      have_viscosity = true;
      iarg += 2;
    } else if (key == "density") {
      need(iarg, 1);
      model.density = number(iarg + 1);
      if (!(model.density >= 0.0))
        error->all(FLERR, "{}: density = {} is out of range (allowed: rho_f >= 0)", STYLE, arg[iarg + 1]);
      iarg += 2;
    } else if (key == "law") {
      need(iarg, 1);
      const std::string law = arg[iarg + 1];
      if (law == "stokes")
        model.law = lub::DragLaw::stokes;
      else if (law == "schiller-naumann")
        model.law = lub::DragLaw::schiller_naumann;
      else
        error->all(FLERR, "{}: law must be stokes or schiller-naumann, got '{}'", STYLE, law);
      iarg += 2;
    } else if (key == "hindrance") {
      need(iarg, 1);
      const std::string h = arg[iarg + 1];
      iarg += 2;
      if (h == "none")
        model.hindrance = lub::Hindrance::none;
      else if (h == "di-felice")
        model.hindrance = lub::Hindrance::di_felice;
      else if (h == "richardson-zaki") {
        need(iarg - 1, 1);
        model.hindrance = lub::Hindrance::richardson_zaki;
        model.rz_exponent = number(iarg);
        if (!(model.rz_exponent >= 1.0 && model.rz_exponent <= 10.0))
          error->all(FLERR, "{}: richardson-zaki n = {} is out of range (allowed: 1 <= n <= 10)", STYLE, arg[iarg]);
        iarg += 1;
      } else
        error->all(FLERR, "{}: hindrance must be none, richardson-zaki n or di-felice, got '{}'", STYLE, h);
    } else if (key == "velocity") {
      need(iarg, 3);
      for (int d = 0; d < 3; d++) {
        if (utils::strmatch(arg[iarg + 1 + d], "^v_"))
          velocity[d].name = arg[iarg + 1 + d] + 2;
        else
          velocity[d].value = number(iarg + 1 + d);
      }
      iarg += 4;
    } else if (key == "superficial") {
      need(iarg, 1);
      superficial = utils::logical(FLERR, arg[iarg + 1], false, lmp) == 1;
      iarg += 2;
    } else if (key == "buoyancy") {
      need(iarg, 3);
      for (int d = 0; d < 3; d++)
        gravity[d] = number(iarg + 1 + d);
      iarg += 4;
    } else if (key == "bins") {
      need(iarg, 3);
      for (int d = 0; d < 3; d++) {
        nbins[d] = utils::inumeric(FLERR, arg[iarg + 1 + d], false, lmp);
        if (nbins[d] < 1) error->all(FLERR, "{}: bins {} is out of range (allowed: >= 1)", STYLE, nbins[d]);
      }
      bins_given = true;
      iarg += 4;
    } else if (key == "every") {
      need(iarg, 1);
      every = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (every < 1) error->all(FLERR, "{}: every = {} is out of range (allowed: N >= 1)", STYLE, every);
      iarg += 2;
    } else {
      error->all(FLERR,
                 "{}: unknown keyword '{}' (expected viscosity, density, law, hindrance, "
                 "velocity, superficial, buoyancy, bins or every)",
                 STYLE, key);
    }
  }
  if (!have_viscosity) error->all(FLERR, "{}: the viscosity keyword is required", STYLE);
  if ((gravity[0] != 0.0 || gravity[1] != 0.0 || gravity[2] != 0.0) && model.density == 0.0)
    error->all(FLERR, "{}: buoyancy needs the fluid density (density keyword)", STYLE);
  if (model.density == 0.0 && model.law == lub::DragLaw::schiller_naumann)
    model.law = lub::DragLaw::stokes;    // Re = 0 without a fluid density
  if (needs_fraction() && !bins_given)
    error->all(FLERR, "{}: hindrance and superficial need the bins keyword for the solid fraction", STYLE);
  if (domain->triclinic) error->all(FLERR, "{} does not support triclinic boxes", STYLE);

  vector_flag = 1;    // total fluid force on the group (3), mean solid fraction of occupied bins
  size_vector = 4;
  global_freq = 1;
  extvector = 0;
  dynamic_group_allow = 1;
  bin_solid.assign(nbins[0] * nbins[1] * nbins[2], 0.0);
  local_sum.assign(bin_solid.size(), 0.0);
}

FixFluidDrag::~FixFluidDrag()
{
  for (auto &p : atom_velocity)
    memory->destroy(p);
}

int FixFluidDrag::setmask()
{
  return POST_FORCE;
}

bool FixFluidDrag::needs_fraction() const
{
  return model.hindrance != lub::Hindrance::none || superficial;
}

void FixFluidDrag::init()
{
  for (auto &c : velocity) {
    if (c.name.empty()) continue;
    c.ivar = input->variable->find(c.name.c_str());
    if (c.ivar < 0) error->all(FLERR, "{}: variable {} for the fluid velocity does not exist", STYLE, c.name);
    if (input->variable->equalstyle(c.ivar))
      c.per_atom = false;
    else if (input->variable->atomstyle(c.ivar))
      c.per_atom = true;
    else
      error->all(FLERR, "{}: variable {} must be equal-style or atom-style", STYLE, c.name);
  }
  last_fraction_step = -1;
  step_velocity = dynamic_cast<FixStepVelocity *>(modify->get_fix_by_id(FixStepVelocity::ID));
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
  const double bin_volume =
      domain->prd[0] * domain->prd[1] * (domain->dimension == 3 ? domain->prd[2] : 1.0) / bin_solid.size();
  for (double &v : bin_solid)
    v /= bin_volume;
  last_fraction_step = update->ntimestep;
}

void FixFluidDrag::post_force(int /*vflag*/)
{
  const int nlocal = atom->nlocal;
  if (needs_fraction() && (last_fraction_step < 0 || update->ntimestep - last_fraction_step >= every))
    update_solid_fraction();

  // Fluid velocity: constants, equal-style or atom-style variables.
  bool any_per_atom = false;
  for (auto &c : velocity)
    any_per_atom = any_per_atom || c.per_atom;
  if (any_per_atom && atom->nmax > maxatom) {
    maxatom = atom->nmax;
    for (auto &p : atom_velocity) {
      memory->destroy(p);
      memory->create(p, maxatom, "fluid/drag:velocity");
    }
  }
  if (!velocity[0].name.empty() || !velocity[1].name.empty() || !velocity[2].name.empty()) {
    modify->clearstep_compute();
    for (int d = 0; d < 3; d++) {
      Component &c = velocity[d];
      if (c.name.empty()) continue;
      if (c.per_atom)
        input->variable->compute_atom(c.ivar, igroup, atom_velocity[d], 1, 0);
      else
        c.value = input->variable->compute_equal(c.ivar);
    }
    modify->addstep_compute(update->ntimestep + 1);
  }

  // A set-up that continues the last run drags with the velocities of its last step, as that
  // step did (fix_step_velocity.h, kept where the pair style or a wall fix of this plugin is).
  const bool continued = step_velocity && step_velocity->continues();
  double **x = atom->x, **v = continued ? step_velocity->velocity() : atom->v, **f = atom->f;
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
    // Explicit relaxation is stable and exact in steady state while beta dt / m <= 1; beyond,
    // the drag removes the slip in one step and never reverses it.
    beta = std::min(beta, rmass[i] / dt);
    const double buoyant_volume = model.density * lub::sphere_volume(radius[i]);
    for (int d = 0; d < 3; d++) {
      const double force = beta * slip[d] - buoyant_volume * gravity[d];
      f[i][d] += force;
      totals[d] += force;
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
  return 3.0 * maxatom * sizeof(double) + 2.0 * bin_solid.size() * sizeof(double);
}
