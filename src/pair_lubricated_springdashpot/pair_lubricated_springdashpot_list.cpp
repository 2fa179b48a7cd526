/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot: the wet neighbor list trimmed after each build to the
   pairs that can come within a film's reach before the next build
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"

#include "atom.h"
#include "neigh_list.h"
#include "neighbor.h"

using namespace LAMMPS_NS;

// A wet model's list has per-type cutoffs (2 R_max + the film's reach + skin; a radius-based
// list would lose film pairs, init_style): in a polydisperse bed most of its extra entries are
// pairs of smaller spheres that no film can reach before the next build. Until then each atom
// stays within skin / 2 of where the build found it (LAMMPS rebuilds before it moves farther),
// so a pair can close its distance by at most the skin: only entries within
// reach_until_next_build (r_i + r_j + the types' largest film reach, as pass 1 uses, + skin) can
// act before the next build, and the others are dropped in place, as LAMMPS's radius-based lists
// never hold them. The same bound as the film budget's (films_can_exceed_budget).
// Not where another list shares this one's arrays (a copy: a compute or fix asking for the same
// list) or this one is a copy or trimmed from another (its arrays may be the parent's).
double PairLubricatedSpringDashpot::reach_until_next_build(int i, int j, double skin) const
{
  const double *radius = atom->radius;
  return radius[i] + radius[j] + max_reach[index(atom->type[i], atom->type[j])] + skin;
}

bool PairLubricatedSpringDashpot::list_can_be_trimmed() const
{
  if (!list || list->listcopy) return false;
  for (int k = 0; k < neighbor->nlist; k++)
    if (neighbor->lists[k] && neighbor->lists[k] != list && neighbor->lists[k]->listcopy == list) return false;
  return true;
}

void PairLubricatedSpringDashpot::trim_list_to_reach()
{
  trimmed_build = {neighbor->lastcall, neighbor->ncalls};
  if (!trim_enabled || !any_wet || !list_can_be_trimmed()) return;
  const double *x = atom->x[0];
  const double skin = neighbor->skin;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int *jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
    int kept = 0;
    // Branch-free (which entries stay follows no pattern): each entry written at the next free
    // place, which moves on where it stays.
    for (int jj = 0; jj < jnum; jj++) {
      const int entry = jlist[jj];
      const int j = entry & NEIGHMASK;
      const double delx = xi - x[3 * j], dely = yi - x[3 * j + 1], delz = zi - x[3 * j + 2];
      const double outer = reach_until_next_build(i, j, skin);
      jlist[kept] = entry;
      kept += delx * delx + dely * dely + delz * delz < outer * outer;
    }
    list->numneigh[i] = kept;
  }
}

// Once per build: a pair style with a contact history trims when its fix is told of the build
// (before the history is laid onto the list's entries), the others at their first evaluation
// after it (a set-up that builds no list, `run N pre no`, finds it trimmed already).
void PairLubricatedSpringDashpot::trim_list_if_built()
{
  if (history) return;    // trimmed by the history fix's post_neighbor (history->before_mapping)
  if (trimmed_build.first == neighbor->lastcall && trimmed_build.second == neighbor->ncalls) return;
  trim_list_to_reach();
}
