/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot: the wet neighbor list trimmed after each build to the
   pairs that can come within a film's reach before the next build
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"

#include "atom.h"
#include "error.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace LAMMPS_NS;

static constexpr const char *STYLE = "Pair style lubricated/springdashpot";

// A wet model's list has per-type cutoffs (2 R_max + the film's reach + skin; a radius-based
// list would lose film pairs, init_style): in a polydisperse bed most of its extra entries are
// pairs of smaller spheres that no film can reach before the next build. Until then each atom
// stays within skin / 2 of where the build found it (LAMMPS rebuilds before it moves farther),
// so a pair can close its distance by at most the skin: only entries within
// reach_until_next_build (r_i + r_j + the types' largest film reach, as pass 1 uses, + skin) can
// act before the next build, and the others are dropped in place, as LAMMPS's radius-based lists
// never hold them. The same bound as the film budget's (film_budget/film_budget.h).
// Not where another list shares this one's arrays (a copy: a compute or fix asking for the same
// list) or this one is a copy or trimmed from another (its arrays may be the parent's).
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
  follow_radii();
  if (!trim_enabled || !any_wet || !list_can_be_trimmed()) return;
  const double *x = atom->x[0], *radius = atom->radius;
  const int *type = atom->type;
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
      const double outer = reach_until_next_build(radius, type, max_reach.data(), ntypes_alloc + 1, i, j, skin);
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

// The cutoffs of a run come from the largest radius of each type at its setup (init_style,
// init_one), or from pair_coeff cutoff. Radii that grow during the run (fix adapt) can outgrow
// them: at each build the largest radius of each type now enters maxrad (which never shrinks in
// a run) and the film's reach (max_reach: pass 1 and the trim use it), and a type pair whose
// largest contact and film distance now exceeds its cutoff is an error (the list would miss
// pairs of it; LAMMPS's own granular styles go on without a warning).
void PairLubricatedSpringDashpot::follow_radii()
{
  const int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0), now(n + 1, 0.0);
  const double *radius = atom->radius;
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++)
    local[type[i]] = std::max(local[type[i]], radius[i]);
  MPI_Allreduce(local.data(), now.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
  for (int t = 1; t <= n; t++)
    maxrad[t] = std::max(maxrad[t], now[t]);
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j] || maxrad[i] <= 0.0 || maxrad[j] <= 0.0) continue;
      const double reach = largest_film_reach(i, j);
      max_reach[index(i, j)] = max_reach[index(j, i)] = reach;
      // This run's cutoff, as init_one gave it to LAMMPS (Pair::init squares it into cutsq).
      const double needed = maxrad[i] + maxrad[j] + reach, cutoff = std::sqrt(cutsq[i][j]);
      if (needed > cutoff * (1.0 + 1e-12))
        error->all(FLERR,
                   "{} types {} {}: spheres of radius {:.8g} and {:.8g} need a cutoff of {:.8g} (contact{}), "
                   "beyond this run's {:.8g} ({}); where radii grow during a run (fix adapt), set pair_coeff {} {} "
                   "... cutoff to the largest distance they will need and rebuild the neighbor list every step "
                   "(neigh_modify delay 0 every 1 check no)",
                   STYLE, i, j, maxrad[i], maxrad[j], needed, reach > 0.0 ? " and film" : "", cutoff,
                   cutoff_given[index(i, j)] > 0.0 ? "pair_coeff cutoff" : "from the radii at its setup", i, j);
    }
}
