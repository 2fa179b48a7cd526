// The many-body film budget of `model lubricated` in LIGGGHTS (fix_lubricated_film_budget.h).
#include "liggghts/fix_lubricated_film_budget.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include "lubricated/film_budget.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <mpi.h>
#include <string>

namespace lubricated {
namespace liggghts {

namespace {

// LIGGGHTS registers its fix styles at compile time, in Modify's private style map. This fix is
// added to that map at run time, through the one access C++ grants to private members: a
// pointer to member named in an explicit instantiation.
using FixCreator = LAMMPS_NS::Fix *(*) (LAMMPS_NS::LAMMPS *, int, char **);
using FixMap = std::map<std::string, FixCreator>;
using FixMapMember = FixMap *LAMMPS_NS::Modify::*;

FixMapMember fix_map_member();
template <FixMapMember member> struct FixMapAccess {
  friend FixMapMember fix_map_member() { return member; }
};
template struct FixMapAccess<&LAMMPS_NS::Modify::fix_map>;

LAMMPS_NS::Fix *create_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  return new FixLubricatedFilmBudget(lmp, narg, arg);
}

}    // namespace

FixLubricatedFilmBudget::FixLubricatedFilmBudget(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg)
{
  comm_forward = 1;    // scales
  comm_reverse = 3;    // loads (1), force corrections (3)
}

int FixLubricatedFilmBudget::setmask()
{
  return LAMMPS_NS::FixConst::PRE_FINAL_INTEGRATE;
}

FixLubricatedFilmBudget *FixLubricatedFilmBudget::find(LAMMPS_NS::LAMMPS *lmp, bool create)
{
  LAMMPS_NS::Modify *modify = lmp->modify;
  int index = modify->find_fix(id_name);
  if (!create) return index < 0 ? nullptr : static_cast<FixLubricatedFilmBudget *>(modify->fix[index]);
  int last_wall = -1;
  for (int k = 0; k < modify->nfix; k++)
    if (std::strncmp(modify->fix[k]->style, "wall/gran", 9) == 0) last_wall = k;
  if (index >= 0 && index > last_wall) return static_cast<FixLubricatedFilmBudget *>(modify->fix[index]);
  // Absent, or before a wall added since: (re)created at the end (it holds nothing between steps).
  if (index >= 0) modify->delete_fix(id_name);
  FixMap *styles = modify->*fix_map_member();
  if (styles->find(style_name) == styles->end()) (*styles)[style_name] = &create_fix;
  std::string id = id_name, group = "all", style = style_name;
  char *arg[3] = {&id[0], &group[0], &style[0]};
  modify->add_fix(3, arg);
  return static_cast<FixLubricatedFilmBudget *>(modify->fix[modify->find_fix(id_name)]);
}

void FixLubricatedFilmBudget::begin()
{
  const int nall = atom->nlocal + atom->nghost;
  newton_pair_ = force->newton_pair;
  nlocal_ = atom->nlocal;
  if (static_cast<int>(load_.size()) < nall) {
    load_.resize(atom->nmax);
    scale_.resize(atom->nmax);
    correction_.resize(3 * static_cast<size_t>(atom->nmax));
  }
  std::fill(load_.begin(), load_.begin() + nall, 0.0);
  records_.clear();
  open_ = true;
}

void FixLubricatedFilmBudget::init()
{
  active_ = participants_ > 0 && !limit_pair_;
  participants_ = 0;
  limit_pair_ = false;
  records_.clear();
  open_ = false;
}

void FixLubricatedFilmBudget::setup(int)
{
  finish();
}

void FixLubricatedFilmBudget::pre_final_integrate()
{
  finish();
}

// Loads summed on the owners, scales sent to the ghosts, then every film whose atoms are over
// budget is scaled by 1 / max(1, D_i, D_j): its (s - 1) f added to i, -(s - 1) f to j.
void FixLubricatedFilmBudget::finish()
{
  // Collective on every rank, whether it saw films or not.
  if (!active_) {
    records_.clear();
    open_ = false;
    return;
  }
  if (!open_) begin();
  open_ = false;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (nlocal != nlocal_ || static_cast<int>(load_.size()) < nall)
    error->one(FLERR, "model lubricated: atoms changed between the force and the film budget");
  if (newton_pair_) {
    exchange_ = Exchange::load;
    comm->reverse_comm_fix(this);
  }
  const int *mask = atom->mask;
  int over = 0;
  for (int i = 0; i < nlocal; i++) {
    scale_[i] = (mask[i] & frozen_group_bit_) ? 1.0 : film_scale_of_load(load_[i]);
    over |= scale_[i] < 1.0;
  }
  // Most steps of most beds leave every film whole: then nothing travels and nothing is redone.
  int any_over = 0;
  MPI_Allreduce(&over, &any_over, 1, MPI_INT, MPI_MAX, world);
  if (!any_over) return;
  exchange_ = Exchange::scale;
  comm->forward_comm_fix(this);
  std::fill(correction_.begin(), correction_.begin() + 3 * static_cast<size_t>(nall), 0.0);
  for (const Record &r : records_) {
    const double s = r.j >= 0 ? std::min(scale_[r.i], scale_[r.j]) : scale_[r.i];
    if (s == 1.0) continue;
    for (int d = 0; d < 3; d++) {
      const double df = (s - 1.0) * r.f[d];
      correction_[3 * r.i + d] += df;
      if (r.j >= 0) correction_[3 * r.j + d] -= df;
    }
  }
  // The pair's ghost forces were already summed on their owners: send the corrections after.
  if (newton_pair_) {
    exchange_ = Exchange::correction;
    comm->reverse_comm_fix(this);
  }
  double **f = atom->f;
  for (int i = 0; i < nlocal; i++)
    for (int d = 0; d < 3; d++) f[i][d] += correction_[3 * i + d];
}

int FixLubricatedFilmBudget::pack_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; k++) buf[k] = scale_[list[k]];
  return 1;
}

void FixLubricatedFilmBudget::unpack_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) scale_[first + k] = buf[k];
}

int FixLubricatedFilmBudget::pack_reverse_comm(int n, int first, double *buf)
{
  if (exchange_ == Exchange::load) {
    for (int k = 0; k < n; k++) buf[k] = load_[first + k];
    return 1;
  }
  std::copy_n(&correction_[3 * static_cast<size_t>(first)], 3 * n, buf);
  return 3;
}

void FixLubricatedFilmBudget::unpack_reverse_comm(int n, int *list, double *buf)
{
  if (exchange_ == Exchange::load) {
    for (int k = 0; k < n; k++) load_[list[k]] += buf[k];
    return;
  }
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) correction_[3 * list[k] + d] += buf[3 * k + d];
}

}    // namespace liggghts
}    // namespace lubricated
