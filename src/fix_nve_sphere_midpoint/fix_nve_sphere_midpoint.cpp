/* ----------------------------------------------------------------------
   fix nve/sphere/midpoint (see doc/fix_nve_sphere_midpoint.rst)

     X~ = X^n + dt/2 V^n,  V~ = 3/2 V^n - 1/2 V^(n-1)        initial_integrate
     forces F(X~, V~) (pair styles, walls, gravity, ...)
     V^(n+1) = V^n + dt F / m                                final_integrate
     X^(n+1) = X^n + dt (V^(n+1) + V^n) / 2 = X~ + dt/2 V^(n+1)

   Angular velocities follow the same scheme with I = 2/5 m r^2. The last form of the
   position update needs no copy of X^n, so periodic remapping between the two halves of
   the step is harmless. An atom's first step (after the fix or the atom is created) uses
   V^(n-1) = V^n and, when it follows a run set-up, the set-up forces F^0 for a second-order
   first drift X~ = X^0 + dt/2 V^0 + dt^2/8 F^0 / m: the step-exact contact then places X~
   on the collision's trajectory (contact_step.h).
------------------------------------------------------------------------- */

#include "fix_nve_sphere_midpoint.h"

#include "unit_style/unit_style.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static constexpr const char *STYLE = "Fix nve/sphere/midpoint";

FixNVESphereMidpoint::FixNVESphereMidpoint(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  require_supported_units(lmp, STYLE);
  if (narg > 3) error->all(FLERR, "{}: unknown keyword '{}' (the fix takes no arguments)", STYLE, arg[3]);
  if (!(atom->radius_flag && atom->rmass_flag && atom->omega_flag && atom->torque_flag))
    error->all(FLERR, "{} requires atom_style sphere", STYLE);

  time_integrate = 1;
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange = NVALUES;
  comm_forward = 3;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++)
    set_arrays(i);
}

FixNVESphereMidpoint *FixNVESphereMidpoint::in_use(LAMMPS *lmp, const char *who)
{
  FixNVESphereMidpoint *midpoint = nullptr;
  Fix *other = nullptr;
  for (Fix *fix : lmp->modify->get_fix_list()) {
    if (!fix->time_integrate) continue;
    auto *candidate = dynamic_cast<FixNVESphereMidpoint *>(fix);
    if (candidate && !midpoint)
      midpoint = candidate;
    else if (!other)
      other = fix;
  }
  if (midpoint && other)
    lmp->error->all(FLERR,
                    "{}: fix {} (nve/sphere/midpoint) must be the only time integration: fix {} ({}) moves "
                    "atoms too, and their contacts would take the velocities of the run's set-up (the "
                    "contacts take every atom's step velocity from the midpoint fix); integrate all moving "
                    "spheres with one fix nve/sphere/midpoint, or use fix nve/sphere for all",
                    who, midpoint->id, other->id, other->style);
  return midpoint;
}

FixNVESphereMidpoint::~FixNVESphereMidpoint()
{
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(state);
}

int FixNVESphereMidpoint::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE | PRE_FORCE;
}

// Ghost atoms get V^n once the neighbor lists and ghosts of this step exist.
void FixNVESphereMidpoint::setup_pre_force(int /*vflag*/)
{
  // Before the first step V^n is the current velocity.
  for (int i = 0; i < atom->nlocal; i++)
    for (int d = 0; d < 3; d++)
      state[i][6 + d] = atom->v[i][d];
  comm->forward_comm(this);
}

void FixNVESphereMidpoint::pre_force(int /*vflag*/)
{
  comm->forward_comm(this);
}

int FixNVESphereMidpoint::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++)
      buf[m++] = state[list[k]][6 + d];
  return m;
}

void FixNVESphereMidpoint::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++)
      state[i][6 + d] = buf[m++];
}

void FixNVESphereMidpoint::init()
{
  dt = update->dt;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && radius[i] == 0.0)
      error->one(FLERR, "{} requires extended particles (radius > 0)", STYLE);
}

void FixNVESphereMidpoint::reset_dt()
{
  dt = update->dt;
}

void FixNVESphereMidpoint::initial_integrate(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double half_dt = 0.5 * dt;
  double **f = atom->f;
  const double *rmass = atom->rmass;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *s = state[i];
    if (s[FIRST_STEP] != 0.0)    // f holds the set-up forces of this run
      for (int d = 0; d < 3; d++)
        x[i][d] += 0.125 * dt * dt * f[i][d] / rmass[i];
    for (int d = 0; d < 3; d++) {
      s[6 + d] = v[i][d];
      s[9 + d] = omega[i][d];
      x[i][d] += half_dt * v[i][d];
      v[i][d] = 1.5 * s[6 + d] - 0.5 * s[d];
      omega[i][d] = 1.5 * s[9 + d] - 0.5 * s[3 + d];
    }
  }
}

void FixNVESphereMidpoint::final_integrate()
{
  double **x = atom->x, **v = atom->v, **f = atom->f;
  double **omega = atom->omega, **torque = atom->torque;
  const double *rmass = atom->rmass, *radius = atom->radius;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double half_dt = 0.5 * dt;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *s = state[i];
    const double dt_over_m = dt / rmass[i];
    const double dt_over_inertia = dt / (0.4 * rmass[i] * radius[i] * radius[i]);
    for (int d = 0; d < 3; d++) {
      const double v_new = s[6 + d] + dt_over_m * f[i][d];
      x[i][d] += half_dt * v_new;
      s[d] = s[6 + d];
      v[i][d] = v_new;
      s[3 + d] = s[9 + d];
      omega[i][d] = s[9 + d] + dt_over_inertia * torque[i][d];
    }
    s[FIRST_STEP] = 0.0;
  }
}

double FixNVESphereMidpoint::memory_usage()
{
  return (double)atom->nmax * NVALUES * sizeof(double);
}

void FixNVESphereMidpoint::grow_arrays(int nmax)
{
  memory->grow(state, nmax, NVALUES, "nve/sphere/midpoint:state");
}

void FixNVESphereMidpoint::copy_arrays(int i, int j, int /*delflag*/)
{
  memcpy(state[j], state[i], NVALUES * sizeof(double));
}

// New atoms (create_atoms, fix pour, ...) start with V^(n-1) = V^n. Those created within a
// step (fix pour) have had no set-up forces: final_integrate clears the flag first.
void FixNVESphereMidpoint::set_arrays(int i)
{
  for (int d = 0; d < 3; d++) {
    state[i][d] = state[i][6 + d] = atom->v[i][d];
    state[i][3 + d] = state[i][9 + d] = atom->omega[i][d];
  }
  state[i][FIRST_STEP] = 1.0;
}

int FixNVESphereMidpoint::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < NVALUES; k++)
    buf[k] = state[i][k];
  return NVALUES;
}

int FixNVESphereMidpoint::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < NVALUES; k++)
    state[nlocal][k] = buf[k];
  return NVALUES;
}

// Restart files hold V^(n-1), omega^(n-1) and the first-step flag: written between steps,
// that is all the scheme needs to continue exactly.
int FixNVESphereMidpoint::pack_restart(int i, double *buf)
{
  buf[0] = RESTART_SIZE;
  for (int k = 0; k < 6; k++)
    buf[1 + k] = state[i][k];
  buf[7] = state[i][FIRST_STEP];
  return RESTART_SIZE;
}

void FixNVESphereMidpoint::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  const int count = static_cast<int>(extra[nlocal][m++]);
  for (int k = 0; k < 6; k++)
    state[nlocal][k] = extra[nlocal][m++];
  state[nlocal][FIRST_STEP] = count > 7 ? extra[nlocal][m] : 0.0;    // older files: 7 values
}

int FixNVESphereMidpoint::size_restart(int /*nlocal*/)
{
  return RESTART_SIZE;
}

int FixNVESphereMidpoint::maxsize_restart()
{
  return RESTART_SIZE;
}
