/* ----------------------------------------------------------------------
   fix wall/lubrication/region: the per-atom friction history per region face (it migrates
   with the atom and is written to restart files) and the region's last displacement (global
   restart), so that a restarted run continues the uninterrupted one.
------------------------------------------------------------------------- */

#include "fix_wall_lubrication_region.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;

// Slot layout: [face id + 1 (0: free), elongation x y z, touched].
double *FixWallLubricationRegion::history_slot(int i, int face)
{
  double *free_slot = nullptr;
  for (int k = 0; k < slots; k++) {
    double *h = history[i] + k * SLOT;
    if (h[0] == face + 1.0) return h;
    if (h[0] == 0.0 && !free_slot) free_slot = h;
  }
  if (!free_slot)    // release_other_slots() left at most tmax faces: cannot happen
    error->one(FLERR, "Fix wall/lubrication/region: no free history slot for face {}", face);
  free_slot[0] = face + 1.0;
  for (int m = 1; m < SLOT; m++)
    free_slot[m] = 0.0;
  return free_slot;
}

void FixWallLubricationRegion::forget_slot(int i, int face)
{
  for (int k = 0; k < slots; k++) {
    double *h = history[i] + k * SLOT;
    if (h[0] == face + 1.0)
      for (int m = 0; m < SLOT; m++)
        h[m] = 0.0;
  }
}

void FixWallLubricationRegion::release_other_slots(int i, const int *near, int n)
{
  for (int k = 0; k < slots; k++) {
    double *h = history[i] + k * SLOT;
    if (h[0] == 0.0) continue;
    bool kept = false;
    for (int c = 0; c < n && !kept; c++)
      kept = h[0] == near[c] + 1.0;
    if (!kept)
      for (int m = 0; m < SLOT; m++)
        h[m] = 0.0;
  }
}

void FixWallLubricationRegion::grow_arrays(int nmax)
{
  memory->grow(history, nmax, slots * SLOT, "wall/lubrication/region:history");
}

void FixWallLubricationRegion::copy_arrays(int i, int j, int /*delflag*/)
{
  std::memcpy(history[j], history[i], sizeof(double) * slots * SLOT);
}

void FixWallLubricationRegion::set_arrays(int i)
{
  for (int k = 0; k < slots * SLOT; k++)
    history[i][k] = 0.0;
}

int FixWallLubricationRegion::pack_exchange(int i, double *buf)
{
  std::memcpy(buf, history[i], sizeof(double) * slots * SLOT);
  return slots * SLOT;
}

int FixWallLubricationRegion::unpack_exchange(int nlocal, double *buf)
{
  std::memcpy(history[nlocal], buf, sizeof(double) * slots * SLOT);
  return slots * SLOT;
}

// Restart: the count of values (LAMMPS's convention), then the slots.
int FixWallLubricationRegion::pack_restart(int i, double *buf)
{
  buf[0] = slots * SLOT + 1;
  std::memcpy(buf + 1, history[i], sizeof(double) * slots * SLOT);
  return slots * SLOT + 1;
}

// As FixWallLubrication's: a fix redefined without a history drops the file's.
void FixWallLubricationRegion::unpack_restart(int nlocal, int nth)
{
  if (!history) return;
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  if (static_cast<int>(extra[nlocal][m]) != slots * SLOT + 1)
    error->one(FLERR,
               "Fix wall/lubrication/region: the restart file's friction history is for a region with {} "
               "faces, region {} has {}",
               (static_cast<int>(extra[nlocal][m]) - 1) / SLOT, region_id, slots);
  std::memcpy(history[nlocal], &extra[nlocal][m + 1], sizeof(double) * slots * SLOT);
}

int FixWallLubricationRegion::size_restart(int /*i*/)
{
  return slots * SLOT + 1;
}

int FixWallLubricationRegion::maxsize_restart()
{
  return slots * SLOT + 1;
}

double FixWallLubricationRegion::memory_usage()
{
  return FixWallLubricationBase::memory_usage() + faces.capacity() * sizeof(int) +
         (history ? static_cast<double>(atom->nmax) * slots * SLOT * sizeof(double) : 0.0);
}

// Global restart: the step of the last evaluation, the region's displacement and angle then,
// and its velocities over that step (V, Omega, P).
void FixWallLubricationRegion::write_restart(FILE *fp)
{
  constexpr int n = 14;
  double list[n] = {static_cast<double>(last_step),
                    last_displacement[0],
                    last_displacement[1],
                    last_displacement[2],
                    last_displacement[3],
                    motion.velocity.x,
                    motion.velocity.y,
                    motion.velocity.z,
                    motion.spin.x,
                    motion.spin.y,
                    motion.spin.z,
                    motion.point.x,
                    motion.point.y,
                    motion.point.z};
  if (comm->me == 0) {
    int size = n * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), n, fp);
  }
}

void FixWallLubricationRegion::restart(char *buf)
{
  double list[14];
  std::memcpy(list, buf, sizeof list);
  last_step = static_cast<bigint>(list[0]);
  for (int k = 0; k < 4; k++)
    last_displacement[k] = list[1 + k];
  motion.velocity = {list[5], list[6], list[7]};
  motion.spin = {list[8], list[9], list[10]};
  motion.point = {list[11], list[12], list[13]};
}
