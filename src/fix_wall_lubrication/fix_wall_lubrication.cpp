/* ----------------------------------------------------------------------
   fix wall/lubrication (see doc/fix_wall_lubrication.rst)

   fix ID group wall/lubrication e_d [keyword value ...] wallstyle lo hi
     keywords as in pair_coeff of pair_style lubricated/springdashpot
     wallstyle = xplane, yplane or zplane; lo, hi = wall positions or NULL
------------------------------------------------------------------------- */

#include "fix_wall_lubrication.h"

#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix wall/lubrication";

FixWallLubrication::FixWallLubrication(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
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
  if (iwall == narg)
    error->all(FLERR, "{}: missing wall style (expected xplane, yplane or zplane lo hi)", STYLE);
  if (iwall + 3 > narg) error->all(FLERR, "{}: {} needs lo and hi positions", STYLE, arg[iwall]);
  if (iwall + 3 < narg)
    error->all(FLERR, "{}: unknown keyword '{}' after the wall positions", STYLE, arg[iwall + 3]);

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
  if (has_lo && has_hi && lo >= hi)
    error->all(FLERR, "{}: lo = {} must be below hi = {}", STYLE, lo, hi);

  scalar_flag = 1;    // elastic energy stored in the wall springs
  vector_flag = 1;    // total force of the walls on the group
  size_vector = 3;
  global_freq = 1;
  extscalar = 1;
  extvector = 1;
  energy_global_flag = 1;
  dynamic_group_allow = 1;
}

int FixWallLubrication::setmask()
{
  return POST_FORCE | MIN_POST_FORCE;
}

void FixWallLubrication::init()
{
  if (comm->me == 0)
    utils::logmesg(lmp, "{}: e_d = {}, t_c = {:.6g} ({:.3g} steps), {}\n", STYLE, coeffs.e_dry,
                   coeffs.contact_time(update->dt), coeffs.steps_per_contact(update->dt),
                   coeffs.wet() ? "film mu_f = " + std::to_string(coeffs.viscosity) : std::string("dry"));
  const std::string problem = lub::validate_time_step(coeffs, update->dt);
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);
  const std::string advice = lub::time_step_warning(coeffs, update->dt);
  if (!advice.empty() && comm->me == 0) error->warning(FLERR, "{}: {}", STYLE, advice);
  reset_dt();
  // Under fix nve/sphere/midpoint the step-exact integration uses the velocity over the
  // last step, which that fix provides (see pair_style lubricated/springdashpot).
  midpoint = nullptr;
  for (auto &ifix : modify->get_fix_by_style("^nve/sphere/midpoint$"))
    midpoint = dynamic_cast<FixNVESphereMidpoint *>(ifix);
}

// k = m (pi^2 + ln^2 e_d) / (N_c dt)^2 follows the time step when N_c is given.
void FixWallLubrication::reset_dt()
{
  model = lub::make_normal_model(coeffs, lub::Partner::wall, update->dt);
}

void FixWallLubrication::setup(int vflag)
{
  post_force(vflag);
}

void FixWallLubrication::min_setup(int vflag)
{
  post_force(vflag);
}

void FixWallLubrication::min_post_force(int vflag)
{
  post_force(vflag);
}

void FixWallLubrication::post_force(int /*vflag*/)
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const double *radius = atom->radius;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const bool at_start = update->setupflag != 0 && !midpoint;    // see contact_step.h

  for (double &s : local_sums) s = 0.0;
  sums_reduced = false;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double r = radius[i];
    // side = +1: lo wall, normal along +axis; side = -1: hi wall, normal along -axis.
    for (int side = 1; side >= -1; side -= 2) {
      if (side == 1 ? !has_lo : !has_hi) continue;
      const double gap = side * (x[i][axis] - (side == 1 ? lo : hi)) - r;
      const double u_n =
          side * (midpoint && model.exact ? midpoint->step_velocity(i)[axis] : v[i][axis]);
      if (!model.acts(gap, r, u_n)) continue;
      const lub::NormalForce fn = lub::normal_force(model, gap, r, rmass[i], u_n, at_start);
      const double force = side * fn.total();
      f[i][axis] += force;
      local_sums[0] += fn.energy;
      local_sums[1 + axis] += force;
    }
  }
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
