/* ----------------------------------------------------------------------
   fix fluid/drag: the Basset history per atom (src/lubricated/fluid_inertia.h). Each atom of
   the group carries its window and tail modes, which migrate with it and go into restart
   files, so that a restarted run continues the history exactly. A step commits the last
   evaluation in pre_force, which a set-up does not call: a set-up that evaluates the forces
   of a step again (a run that continues, a restart) leaves the history as it was.
------------------------------------------------------------------------- */

#include "fix_fluid_drag.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"

#include <cstring>

using namespace LAMMPS_NS;

static constexpr const char *STYLE = "Fix fluid/drag";

void FixFluidDrag::setup_history()
{
  basset = lubricated::BassetHistory(history_window, history_modes, 1.0);    // the layout; rates in init()
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange = basset.size();
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nmax; i++)
    set_arrays(i);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

void FixFluidDrag::pre_force(int /*vflag*/)
{
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) basset.commit(history_state[i]);
}

void FixFluidDrag::grow_arrays(int nmax)
{
  memory->grow(history_state, nmax, basset.size(), "fluid/drag:history");
}

void FixFluidDrag::copy_arrays(int i, int j, int /*delflag*/)
{
  std::memcpy(history_state[j], history_state[i], basset.size() * sizeof(double));
}

void FixFluidDrag::set_arrays(int i)
{
  std::memset(history_state[i], 0, basset.size() * sizeof(double));
}

int FixFluidDrag::pack_exchange(int i, double *buf)
{
  std::memcpy(buf, history_state[i], basset.size() * sizeof(double));
  return basset.size();
}

int FixFluidDrag::unpack_exchange(int nlocal, double *buf)
{
  std::memcpy(history_state[nlocal], buf, basset.size() * sizeof(double));
  return basset.size();
}

int FixFluidDrag::pack_restart(int i, double *buf)
{
  buf[0] = basset.size() + 1;
  std::memcpy(buf + 1, history_state[i], basset.size() * sizeof(double));
  return basset.size() + 1;
}

void FixFluidDrag::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  if (static_cast<int>(extra[nlocal][m]) != basset.size() + 1)
    error->one(FLERR, "{}: the history in the restart file has another size (window or tail changed)", STYLE);
  std::memcpy(history_state[nlocal], &extra[nlocal][m + 1], basset.size() * sizeof(double));
}

int FixFluidDrag::size_restart(int /*i*/)
{
  return basset.size() + 1;
}

int FixFluidDrag::maxsize_restart()
{
  return basset.size() + 1;
}

// Global: the window, the tail modes and the step the tail is laid out for.
void FixFluidDrag::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double data[3] = {static_cast<double>(history_window), static_cast<double>(history_modes), history_dt};
  const int size = sizeof(data);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data, sizeof(double), 3, fp);
}

void FixFluidDrag::restart(char *buf)
{
  double data[3];
  std::memcpy(data, buf, sizeof(data));
  if (static_cast<int>(data[0]) != history_window || static_cast<int>(data[1]) != history_modes)
    error->all(FLERR,
               "{}: the restart file's history has window {} and tail {}, the fix window {} and tail {}: "
               "give the same values",
               STYLE, static_cast<int>(data[0]), static_cast<int>(data[1]), history_window, history_modes);
  history_dt = data[2];
}
