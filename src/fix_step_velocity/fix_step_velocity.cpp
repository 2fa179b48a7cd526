/* ----------------------------------------------------------------------
   fix LUBRICATED_STEP_VELOCITY (see fix_step_velocity.h)
------------------------------------------------------------------------- */

#include "fix_step_velocity.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

static constexpr int VALUES = 6;    // vx vy vz, omega x y z

FixStepVelocity *FixStepVelocity::find_or_create(LAMMPS *lmp)
{
  Fix *fix = lmp->modify->get_fix_by_id(ID);
  if (!fix) fix = lmp->modify->add_fix(std::string(ID) + " all " + ID);
  return dynamic_cast<FixStepVelocity *>(fix);
}

FixStepVelocity::FixStepVelocity(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  comm_forward = VALUES;
  maxexchange = VALUES;
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixStepVelocity::~FixStepVelocity()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(kick);
  memory->destroy(vhalf);
  memory->destroy(whalf);
}

// INITIAL_INTEGRATE: only to release the kicks and the set-up's velocities at the first step.
int FixStepVelocity::setmask()
{
  return POST_NEIGHBOR | INITIAL_INTEGRATE;
}

// The set-up's velocities live from the set-up that continues a run to its first step.
void FixStepVelocity::release_setup_velocities()
{
  memory->destroy(vhalf);
  memory->destroy(whalf);
}

// The kicks live while the state is continuable: from the end of a run that took steps to the
// first step of the next (a `run 0` keeps them); then the per-atom arrays are empty and the
// restart files written in a run say that it cannot be continued from them.
void FixStepVelocity::hold_kicks(bool hold)
{
  if (!hold) {
    memory->destroy(kick);
    return;
  }
  if (kick) return;
  memory->create(kick, atom->nmax, VALUES, "lubricated/step_velocity:kick");
  for (int i = 0; i < atom->nmax; i++)
    set_arrays(i);
}

void FixStepVelocity::initial_integrate(int /*vflag*/)
{
  if (vhalf) release_setup_velocities();
  if (kick) {
    continuable = false;
    hold_kicks(false);
  }
}

// The integrator the reconstruction assumes: fix nve/sphere (v += dt/2 f/m, omega += dt/2
// torque / (2/5 m r^2)) and no other time integration.
bool FixStepVelocity::integrated_by_nve_sphere() const
{
  bool any = false;
  for (Fix *fix : modify->get_fix_list()) {
    if (!fix->time_integrate) continue;
    if (strcmp(fix->style, "nve/sphere") != 0) return false;
    any = true;
  }
  return any;
}

// The last half kick of owned atom i, dt/2 f/m and dt/2 torque / (2/5 m r^2), kept at the end
// of a run while atom->f and atom->torque still hold the last step's (commands between runs may
// migrate or reorder atoms; the forces do not travel with them, the kicks do).
void FixStepVelocity::store_kick(int i)
{
  const double dtf = 0.5 * step_dt * force->ftm2v, m = atom->rmass[i], r = atom->radius[i];
  const double *f = atom->f[i];
  for (int d = 0; d < 3; d++)
    kick[i][d] = dtf * f[d] / m;
  if (!(atom->omega_flag && atom->torque_flag)) return;
  const double *t = atom->torque[i];
  const double dtw = dtf / (0.4 * m * r * r);
  for (int d = 0; d < 3; d++)
    kick[i][3 + d] = dtw * t[d];
}

// After the set-up's migration, before any force: whether this set-up continues the last run,
// and then the last step's velocities v - kick of the owned atoms (velocities set between runs
// included; an atom created since has no kick), then the ghosts'.
void FixStepVelocity::setup_post_neighbor()
{
  continuing = continuable && update->whichflag == 1 && update->dt == step_dt && integrated_by_nve_sphere();
  if (!continuing) return;
  memory->grow(vhalf, atom->nmax, 3, "lubricated/step_velocity:v");
  memory->grow(whalf, atom->nmax, 3, "lubricated/step_velocity:omega");
  const bool spins = atom->omega_flag;
  for (int i = 0; i < atom->nlocal; i++)
    for (int d = 0; d < 3; d++) {
      vhalf[i][d] = atom->v[i][d] - kick[i][d];
      whalf[i][d] = spins ? atom->omega[i][d] - kick[i][3 + d] : 0.0;
    }
  comm->forward_comm(this);
  // A run with steps needs the kicks no more (its post_run stores new ones); `run 0` keeps them.
  if (update->endstep > update->beginstep) {
    continuable = false;
    hold_kicks(false);
  }
}

// A run that took steps of the velocity Verlet leaves a state the next set-up can continue;
// `run 0` leaves it as it was; a minimisation does not.
void FixStepVelocity::post_run()
{
  continuing = false;
  release_setup_velocities();
  if (update->whichflag != 1) {
    continuable = false;
  } else if (update->ntimestep > update->beginstep) {
    continuable = integrated_by_nve_sphere();
    step_dt = update->dt;
    hold_kicks(continuable);
    if (continuable)
      for (int i = 0; i < atom->nlocal; i++)
        store_kick(i);
  }
  if (!continuable) hold_kicks(false);
}

void FixStepVelocity::grow_arrays(int nmax)
{
  if (kick) memory->grow(kick, nmax, VALUES, "lubricated/step_velocity:kick");
  if (vhalf) {
    memory->grow(vhalf, nmax, 3, "lubricated/step_velocity:v");
    memory->grow(whalf, nmax, 3, "lubricated/step_velocity:omega");
  }
}

void FixStepVelocity::copy_arrays(int i, int j, int /*delflag*/)
{
  if (!kick) return;
  for (int k = 0; k < VALUES; k++)
    kick[j][k] = kick[i][k];
}

void FixStepVelocity::set_arrays(int i)
{
  if (!kick) return;
  for (int k = 0; k < VALUES; k++)
    kick[i][k] = 0.0;
}

// Every rank holds the kicks or none (post_run, the first step and restart are collective).
int FixStepVelocity::pack_exchange(int i, double *buf)
{
  if (!kick) return 0;
  for (int k = 0; k < VALUES; k++)
    buf[k] = kick[i][k];
  return VALUES;
}

int FixStepVelocity::unpack_exchange(int nlocal, double *buf)
{
  if (!kick) return 0;
  for (int k = 0; k < VALUES; k++)
    kick[nlocal][k] = buf[k];
  return VALUES;
}

// A ghost that is a periodic image of its owner moves with the owner's velocity, plus, in a box
// that fix deform changes with `remap v`, the box's velocity over the image's offset (as LAMMPS
// communicates atom->v; without it the films and contacts across the box's boundary would see
// the shear rate times the box as a relative velocity at a continued set-up).
int FixStepVelocity::pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  double shift[3] = {0.0, 0.0, 0.0};
  const bool remap = pbc_flag && domain->deform_vremap;
  if (remap) {
    const double *rate = domain->h_rate;    // xx yy zz yz xz xy
    shift[0] = pbc[0] * rate[0] + pbc[5] * rate[5] + pbc[4] * rate[4];
    shift[1] = pbc[1] * rate[1] + pbc[3] * rate[3];
    shift[2] = pbc[2] * rate[2];
  }
  const int *mask = atom->mask;
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int i = list[k];
    const bool shifted = remap && (mask[i] & domain->deform_groupbit);
    for (int d = 0; d < 3; d++)
      buf[m++] = shifted ? vhalf[i][d] + shift[d] : vhalf[i][d];
    for (int d = 0; d < 3; d++)
      buf[m++] = whalf[i][d];
  }
  return m;
}

void FixStepVelocity::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    for (int d = 0; d < 3; d++)
      vhalf[i][d] = buf[m++];
    for (int d = 0; d < 3; d++)
      whalf[i][d] = buf[m++];
  }
}

int FixStepVelocity::pack_restart(int i, double *buf)
{
  if (!kick) {
    buf[0] = 1;
    return 1;
  }
  buf[0] = VALUES + 1;
  for (int k = 0; k < VALUES; k++)
    buf[k + 1] = kick[i][k];
  return VALUES + 1;
}

void FixStepVelocity::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  if (!kick) return;    // a file written in a run, or one that cannot be continued
  const bool stored = static_cast<int>(extra[nlocal][m]) == VALUES + 1;
  for (int k = 0; k < VALUES; k++)
    kick[nlocal][k] = stored ? extra[nlocal][m + 1 + k] : 0.0;
}

int FixStepVelocity::size_restart(int /*i*/)
{
  return kick ? VALUES + 1 : 1;
}

int FixStepVelocity::maxsize_restart()
{
  return VALUES + 1;
}

void FixStepVelocity::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double data[2] = {continuable ? 1.0 : 0.0, step_dt};
  const int size = sizeof(data);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data, sizeof(double), 2, fp);
}

void FixStepVelocity::restart(char *buf)
{
  const auto *data = reinterpret_cast<const double *>(buf);
  continuable = data[0] != 0.0;
  step_dt = data[1];
  hold_kicks(continuable);
}

double FixStepVelocity::memory_usage()
{
  return ((kick ? VALUES : 0.0) + (vhalf ? 6.0 : 0.0)) * atom->nmax * sizeof(double);
}
