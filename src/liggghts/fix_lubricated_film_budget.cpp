// The many-body film budget of `model lubricated` in LIGGGHTS (fix_lubricated_film_budget.h).
#include "liggghts/fix_lubricated_film_budget.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include "liggghts/fix_style_map.h"
#include "liggghts/lubricated_properties.h"
#include "lubricated/contact_network.h"
#include "lubricated/contact_network_message.h"
#include "lubricated/contact_network_ranks.h"
#include "lubricated/film_budget.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <mpi.h>
#include <string>

namespace lubricated {
namespace liggghts {

namespace {

LAMMPS_NS::Fix *create_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  return new FixLubricatedFilmBudget(lmp, narg, arg);
}

}    // namespace

FixLubricatedFilmBudget::FixLubricatedFilmBudget(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  comm_forward = network_values;    // scales (1), network sums (8)
  comm_reverse = network_values;    // loads (1), force corrections (3), network sums (8)
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
  add_fix_style(modify, style_name, &create_fix);
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
  network_on_ = network_pending_;
  network_pending_ = false;
  walls_ = pending_walls_;
  pending_walls_.clear();
  films_can_exceed_ = true;    // until the set-up's bounds say otherwise
  network_due_ = network_warned_ = false;
  network_next_ = 0;    // the first step of each run
}

void FixLubricatedFilmBudget::begin_pass()
{
  if (active()) begin();
  network_due_ = network_on_ && !update->setupflag && update->ntimestep >= network_next_;
  if (network_due_) network_.clear();
}

void FixLubricatedFilmBudget::set_network(int ntypes, const std::vector<double> &normal_load,
                                          const std::vector<double> &bound_load,
                                          const std::vector<Coefficients> &coefficients)
{
  ntypes_ = ntypes;
  network_load_ = normal_load;
  network_bound_ = bound_load;
  coefficients_ = coefficients;
  bool matters = false;
  for (double &b : network_bound_) {
    if (!(b > network_check_load)) b = 0.0;    // network_load_matters(): no record, no check
    matters = matters || b > 0.0;
  }
  network_on_ = network_pending_ = matters;
}

double *FixLubricatedFilmBudget::bound_of_atoms()
{
  const int nall = atom->nlocal + atom->nghost;
  if (static_cast<int>(load_.size()) < nall) {
    load_.resize(atom->nmax);
    scale_.resize(atom->nmax);
    correction_.resize(3 * static_cast<size_t>(atom->nmax));
  }
  std::fill(load_.begin(), load_.begin() + nall, 0.0);
  return load_.data();
}

// Collective. The walls' bounds with the spheres' own masses (a rigid body's is larger: its
// bound smaller), every atom counted as near every wall.
void FixLubricatedFilmBudget::decide_skip()
{
  const int nlocal = atom->nlocal;
  const double *radius = atom->radius, *rmass = atom->rmass, dt = update->dt;
  double *bound = load_.data();
  newton_pair_ = force->newton_pair;
  if (newton_pair_) {
    exchange_ = Exchange::load;
    comm->reverse_comm_fix(this);
  }
  const int *type = atom->type;
  for (const WallFilms &wall : walls_)
    for (int i = 0; i < nlocal; i++)
      bound[i] += wall.mesh ? 1.0 : film_share_bound(wall.by_type[type[i]], radius[i], rmass[i], dt);
  const int over = any_load_can_exceed_budget(bound, nlocal) ? 1 : 0;
  int any_over = 0;
  MPI_Allreduce(&over, &any_over, 1, MPI_INT, MPI_MAX, world);
  films_can_exceed_ = any_over != 0;
}

void FixLubricatedFilmBudget::setup(int)
{
  finish();
}

void FixLubricatedFilmBudget::pre_final_integrate()
{
  finish();
}

// Collective on every rank, whether it saw films and contacts or not.
void FixLubricatedFilmBudget::finish()
{
  if (active()) {
    finish_films();
  } else {
    records_.clear();
    open_ = false;
  }
  if (network_due_) {
    network_due_ = false;
    network_next_ = update->ntimestep + network_check_interval;
    check_network();
  }
}

// Loads summed on the owners, scales sent to the ghosts, then every film whose atoms are over
// budget is scaled by 1 / max(1, D_i, D_j): its (s - 1) f added to i, -(s - 1) f to j.
void FixLubricatedFilmBudget::finish_films()
{
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
    const bool held = (mask[i] & hold_bits_) || !(mask[i] & integrate_bits_);
    scale_[i] = held ? 1.0 : film_scale_of_load(load_[i]);
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
    for (int d = 0; d < 3; d++)
      f[i][d] += correction_[3 * i + d];
}

// Forward: scales (1 per atom) or network sums (network_values); the return is per atom.
int FixLubricatedFilmBudget::pack_comm(int n, int *list, double *buf, int, int *)
{
  if (exchange_ == Exchange::network_sums) {
    for (int k = 0; k < n; k++)
      std::copy_n(&network_sums_[network_values * static_cast<size_t>(list[k])], network_values,
                  buf + network_values * k);
    return network_values;
  }
  for (int k = 0; k < n; k++)
    buf[k] = scale_[list[k]];
  return 1;
}

void FixLubricatedFilmBudget::unpack_comm(int n, int first, double *buf)
{
  if (exchange_ == Exchange::network_sums) {
    std::copy_n(buf, network_values * n, &network_sums_[network_values * static_cast<size_t>(first)]);
    return;
  }
  for (int k = 0; k < n; k++)
    scale_[first + k] = buf[k];
}

// Reverse: loads (1), force corrections (3) or network sums, added on the owners.
int FixLubricatedFilmBudget::pack_reverse_comm(int n, int first, double *buf)
{
  const int width = exchange_ == Exchange::load ? 1 : exchange_ == Exchange::correction ? 3 : network_values;
  const double *values = exchange_ == Exchange::load         ? load_.data()
                         : exchange_ == Exchange::correction ? correction_.data()
                                                             : network_sums_.data();
  std::copy_n(values + width * static_cast<size_t>(first), width * n, buf);
  return width;
}

void FixLubricatedFilmBudget::unpack_reverse_comm(int n, int *list, double *buf)
{
  const int width = exchange_ == Exchange::load ? 1 : exchange_ == Exchange::correction ? 3 : network_values;
  double *values = exchange_ == Exchange::load         ? load_.data()
                   : exchange_ == Exchange::correction ? correction_.data()
                                                       : network_sums_.data();
  for (int k = 0; k < n; k++)
    for (int q = 0; q < width; q++)
      values[width * static_cast<size_t>(list[k]) + q] += buf[width * k + q];
}

// The contacts' per-atom sums on every copy of each atom, then the bounds of each contact
// (contact_network.h): an ERROR where the lower bound proves a growing mode, a WARNING (once a
// run) where it makes one likely and the upper bound cannot exclude it.
void FixLubricatedFilmBudget::check_network()
{
  constexpr int nv = network_values;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (network_sums_.size() < nv * static_cast<size_t>(nall)) network_sums_.resize(nv * static_cast<size_t>(atom->nmax));
  std::fill(network_sums_.begin(), network_sums_.begin() + nv * static_cast<size_t>(nall), 0.0);
  for (const NetworkContact &c : network_) {
    lubricated::add_network_contact(&network_sums_[nv * c.i], network_load_[c.type_pair], network_bound_[c.type_pair],
                                    c.m_e, c.n);
    if (newton_pair_ || c.j < nlocal)
      lubricated::add_network_contact(&network_sums_[nv * c.j], network_load_[c.type_pair], network_bound_[c.type_pair],
                                      c.m_e, c.n);
  }
  exchange_ = Exchange::network_sums;
  if (newton_pair_) comm->reverse_comm_fix(this);
  comm->forward_comm_fix(this);

  // Each contact's bounds; the worst over all ranks decides (contact_network_ranks.h).
  NetworkScores scores(comm->me);
  for (size_t k = 0; k < network_.size(); k++) {
    const NetworkContact &c = network_[k];
    const double *si = &network_sums_[nv * c.i], *sj = &network_sums_[nv * c.j];
    const double bound = network_bound_[c.type_pair];
    scores.add(static_cast<int>(k),
               network_lower_quotient(network_load_[c.type_pair], c.m_e, c.n, si, c.m_i, sj, c.m_j),
               network_upper_row(bound, c.m_e, si, c.m_i, sj, c.m_j), bound);
  }
  NetworkFinding found;
  auto describe = [&](int k, int *types, long long *tags, double *contacts) {
    const int ij[2] = {network_[k].i, network_[k].j};
    for (int s = 0; s < 2; s++) {
      types[s] = atom->type[ij[s]];
      tags[s] = atom->tag[ij[s]];
      contacts[s] = network_sums_[nv * ij[s] + nv - 1];
    }
  };
  if (!scores.decide(world, network_warned_, describe, found)) return;
  // LIGGGHTS's Error keeps a pointer to the text: it must outlive this call. The bounds count
  // LIGGGHTS's sampled tangential spring (network_loads): the advice must too.
  static std::string message;
  message = with_property_names(network_message(
      "model lubricated", coefficients_[found.type_i * (ntypes_ + 1) + found.type_j], update->dt, found, true));
  if (found.unstable) error->all(FLERR, message.c_str());
  if (comm->me == 0) error->warning(FLERR, message.c_str());
}

}    // namespace liggghts
}    // namespace lubricated
