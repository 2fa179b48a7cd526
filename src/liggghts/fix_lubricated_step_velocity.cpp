// The step velocities of `model lubricated` at a LIGGGHTS set-up (fix_lubricated_step_velocity.h).
#include "liggghts/fix_lubricated_step_velocity.h"

#include "atom.h"
#include "comm.h"
#include "fix_nve_sphere.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "liggghts/fix_style_map.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <mpi.h>
#include <string>
#include <vector>

namespace lubricated {
namespace liggghts {

namespace {

constexpr int values = 3;    // the kick of v

LAMMPS_NS::Fix *create_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  return new FixLubricatedStepVelocity(lmp, narg, arg);
}

// fix nve/sphere's added-mass divisor 1 + C_add rho_f / rho_p (1 without `update CAddRhoFluid`),
// protected: read through a class derived for that purpose only.
struct NveSphereAddedMass : LAMMPS_NS::FixNVESphere {
  static double of(LAMMPS_NS::Fix *fix)
  {
    return static_cast<LAMMPS_NS::FixNVESphere *>(fix)->*(&NveSphereAddedMass::onePlusCAddRhoFluid_);
  }
};

struct RadiusWatch {
  LAMMPS_NS::LAMMPS *lmp;
  double covered;
  std::function<void(double)> smaller;
};

std::map<const void *, RadiusWatch> &radius_watches()
{
  static std::map<const void *, RadiusWatch> watches;
  return watches;
}

}    // namespace

void watch_radius(LAMMPS_NS::LAMMPS *lmp, const void *model, double covered, std::function<void(double)> smaller)
{
  radius_watches()[model] = RadiusWatch{lmp, covered, std::move(smaller)};
}

void forget_radius(const void *model)
{
  radius_watches().erase(model);
}

FixLubricatedStepVelocity *FixLubricatedStepVelocity::find_or_create(LAMMPS_NS::LAMMPS *lmp)
{
  LAMMPS_NS::Modify *modify = lmp->modify;
  int index = modify->find_fix(id_name);
  if (index < 0) {
    add_fix_style(modify, style_name, &create_fix);
    std::string id = id_name, group = "all", style = style_name;
    char *arg[3] = {&id[0], &group[0], &style[0]};
    modify->add_fix(3, arg);
    index = modify->find_fix(id_name);
  }
  return static_cast<FixLubricatedStepVelocity *>(modify->fix[index]);
}

FixLubricatedStepVelocity::FixLubricatedStepVelocity(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  comm_forward = values;
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nmax; i++)
    set_arrays(i);
  atom->add_callback(0);    // grow
  atom->add_callback(1);    // restart
}

FixLubricatedStepVelocity::~FixLubricatedStepVelocity()
{
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(kick_);
}

int FixLubricatedStepVelocity::setmask()
{
  return LAMMPS_NS::FixConst::PRE_NEIGHBOR;
}

// The integration the kicks assume: fix nve/sphere without added mass, and no other.
bool FixLubricatedStepVelocity::integrated_by_nve_sphere()
{
  integrated_bits_ = 0;
  for (int k = 0; k < modify->nfix; k++) {
    LAMMPS_NS::Fix *fix = modify->fix[k];
    if (!fix->time_integrate) continue;
    if (std::strcmp(fix->style, "nve/sphere") != 0 || NveSphereAddedMass::of(fix) != 1.0) return false;
    integrated_bits_ |= fix->groupbit;
  }
  return integrated_bits_ != 0;
}

// Before every neighbor list build (atoms inserted since the last one are there): the smallest
// radius, for the models that watch it. Collective, as every rank holds the same watches.
void FixLubricatedStepVelocity::check_radii()
{
  std::vector<RadiusWatch *> watching;
  for (auto &w : radius_watches())
    if (w.second.lmp == lmp) watching.push_back(&w.second);
  if (watching.empty()) return;
  double local = std::numeric_limits<double>::infinity(), smallest = local;
  for (int i = 0; i < atom->nlocal; i++)
    local = std::min(local, atom->radius[i]);
  MPI_Allreduce(&local, &smallest, 1, MPI_DOUBLE, MPI_MIN, world);
  for (RadiusWatch *w : watching)
    if (smallest < w->covered) {
      w->covered = smallest;
      w->smaller(smallest);
    }
}

void FixLubricatedStepVelocity::pre_neighbor()
{
  check_radii();
}

// After the set-up's migration and borders, before any force: whether the set-up continues the
// last run, and then the ghosts' kicks (velocities set between runs count as that step's).
void FixLubricatedStepVelocity::setup_pre_neighbor()
{
  check_radii();
  continuing_ = continuable_ && update->whichflag == 1 && update->dt == step_dt_ && integrated_by_nve_sphere();
  if (continuing_) comm->forward_comm_fix(this);
}

// A run that took steps leaves the kicks of its last step; `run 0` leaves them as they were.
// Atoms no fix nve/sphere moves keep their velocity: no kick.
void FixLubricatedStepVelocity::post_run()
{
  continuing_ = false;
  if (update->whichflag != 1) {
    continuable_ = false;
    return;
  }
  if (update->ntimestep <= update->beginstep) return;
  continuable_ = integrated_by_nve_sphere();
  step_dt_ = update->dt;
  if (!continuable_) return;
  const double dtf = 0.5 * step_dt_ * force->ftm2v;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    for (int d = 0; d < values; d++)
      kick_[i][d] = (mask[i] & integrated_bits_) ? dtf * atom->f[i][d] / atom->rmass[i] : 0.0;
}

void FixLubricatedStepVelocity::grow_arrays(int nmax)
{
  memory->grow(kick_, nmax, values, "lubricated/step_velocity:kick");
}

void FixLubricatedStepVelocity::copy_arrays(int i, int j, int)
{
  for (int d = 0; d < values; d++)
    kick_[j][d] = kick_[i][d];
}

void FixLubricatedStepVelocity::set_arrays(int i)
{
  for (int d = 0; d < values; d++)
    kick_[i][d] = 0.0;
}

int FixLubricatedStepVelocity::pack_exchange(int i, double *buf)
{
  for (int d = 0; d < values; d++)
    buf[d] = kick_[i][d];
  return values;
}

int FixLubricatedStepVelocity::unpack_exchange(int nlocal, double *buf)
{
  for (int d = 0; d < values; d++)
    kick_[nlocal][d] = buf[d];
  return values;
}

int FixLubricatedStepVelocity::pack_restart(int i, double *buf)
{
  buf[0] = values + 1;
  for (int d = 0; d < values; d++)
    buf[d + 1] = kick_[i][d];
  return values + 1;
}

void FixLubricatedStepVelocity::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  for (int d = 0; d < values; d++)
    kick_[nlocal][d] = extra[nlocal][m + 1 + d];
}

int FixLubricatedStepVelocity::size_restart(int)
{
  return values + 1;
}

int FixLubricatedStepVelocity::maxsize_restart()
{
  return values + 1;
}

void FixLubricatedStepVelocity::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double data[2] = {continuable_ ? 1.0 : 0.0, step_dt_};
  const int size = sizeof(data);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data, sizeof(double), 2, fp);
}

void FixLubricatedStepVelocity::restart(char *buf)
{
  const auto *data = reinterpret_cast<const double *>(buf);
  continuable_ = data[0] != 0.0;
  step_dt_ = data[1];
}

int FixLubricatedStepVelocity::pack_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int d = 0; d < values; d++)
      buf[m++] = kick_[list[k]][d];
  return values;    // LIGGGHTS's Comm::forward_comm_fix takes the values per atom
}

void FixLubricatedStepVelocity::unpack_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < values; d++)
      kick_[i][d] = buf[m++];
}

double FixLubricatedStepVelocity::memory_usage()
{
  return static_cast<double>(atom->nmax) * values * sizeof(double);
}

}    // namespace liggghts
}    // namespace lubricated
