/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot: the many-body parts of a dense bed, the film budget
   (lubricated/film_budget.h), the contact-network check (lubricated/contact_network.h) and
   the communication of their per-atom sums
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"
#include "vector_pairs.h"

#include "fix_contact_history/fix_contact_history.h"
#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_wall_lubrication/fix_wall_lubrication_base.h"
#include "lubricated/contact_network.h"
#include "lubricated/contact_network_message.h"
#include "lubricated/contact_network_ranks.h"
#include "lubricated/film_budget.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <unordered_map>

using namespace LAMMPS_NS;
namespace lub = lubricated;

static constexpr const char *STYLE = "Pair style lubricated/springdashpot";

// Until the next neighbor list build a pair closes by at most the skin, so only the pairs of the
// list whose gap is below the film's reach plus the skin can have a film. Each atom's sum of
// those contacts' share bounds (and its wet walls') bounds its load: where no sum exceeds 1
// the budget would scale nothing and is skipped until the next build (or a new time step).
// The bounds use the spheres' own masses, which no contact mass exceeds (contact_mass.h).
// First with one ceiling for every pair's share (film_budget.h, pair_film_share_ceiling): where no
// atom's sum of those reaches 1, neither do the pairs' own bounds, whose logarithms are then spared.
bool PairLubricatedSpringDashpot::films_can_exceed_budget()
{
  double **x = atom->x;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, newton_pair = force->newton_pair;
  const double dt = update->dt, skin = neighbor->skin;
  film_bound_dt = dt;
  if (static_cast<int>(load_of_atom.size()) < nall) {
    load_of_atom.resize(atom->nmax);
    scale_of_atom.resize(atom->nmax);
  }
  double *bound = load_of_atom.data();
  // Each atom's sum of its pairs' bounds bound_of(i, j, rsq), its wet walls' added, over all
  // ranks: whether any can exceed the budget.
  auto can_exceed = [&](auto &&bound_of) {
    std::fill(bound, bound + nall, 0.0);
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int *jlist = list->firstneigh[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
        const double b = bound_of(i, j, delx * delx + dely * dely + delz * delz);
        bound[i] += b;
        if (newton_pair || j < nlocal) bound[j] += b;
      }
    }
    for (auto wall : walls)
      wall->add_film_share_bounds(bound, nlocal);
    if (newton_pair) {
      comm_what = COMM_LOAD;
      comm->reverse_comm(this);
    }
    const int over = lub::any_load_can_exceed_budget(bound, nlocal) ? 1 : 0;
    int any = 0;
    MPI_Allreduce(&over, &any, 1, MPI_INT, MPI_MAX, world);
    return any != 0;
  };

  double r_min = INFINITY, r_max = 0.0, m_min = INFINITY;
  for (int k = 0; k < nall; k++) {
    r_min = std::min(r_min, radius[k]), r_max = std::max(r_max, radius[k]);
    m_min = std::min(m_min, rmass[k]);
  }
  const int stride = ntypes_alloc + 1;
  double ceiling = 0.0;
  for (int a = 1; a < stride; a++)
    for (int b = 1; b < stride; b++) {
      const lub::ContactModel &model = models[index(a, b)];
      ceiling = std::max(
          ceiling, lub::pair_film_share_ceiling(model.tangential, model.normal.lubrication, r_min, r_max, m_min, dt));
    }
  // The ceiling for every pair the types' largest film reach (max_reach) plus the skin allows.
  const bool ceiling_can_exceed = can_exceed([&](int i, int j, double rsq) {
    const double reach = reach_until_next_build(i, j, skin);
    return rsq < reach * reach ? ceiling : 0.0;
  });
  if (!ceiling_can_exceed) return false;
  return can_exceed([&](int i, int j, double rsq) {
    const lub::ContactModel &model = models[index(type[i], type[j])];
    const lub::Lubrication &film = model.normal.lubrication;
    if (!film.active()) return 0.0;
    const lub::FilmRadius radius_ij = lub::film_radius_pair(radius[i], radius[j]);
    const double reach = radius[i] + radius[j] + film.reach(radius_ij.value) + skin;
    if (rsq >= reach * reach) return 0.0;
    // The contact's share is the larger of its normal and shear films' (film_budget.h).
    const double m_e = lub::reduced_mass(rmass[i], rmass[j]);
    const double reduced_radius = radius[i] * radius[j] / (radius[i] + radius[j]);
    return std::max(lub::film_share_bound(film, radius_ij.value, m_e, dt),
                    lub::shear_film_share_bound(model.tangential, film, radius_ij.value, reduced_radius,
                                                lub::tangential_mass_ratio * m_e, dt));
  });
}

// Owned atoms' inverse contact masses, then the ghosts' (a rigid body's mass is known to the
// owner of the atom only). Atoms change rank and index only when the lists are rebuilt.
void PairLubricatedSpringDashpot::update_inverse_mass()
{
  if (static_cast<int>(inverse_mass.size()) < atom->nlocal + atom->nghost) inverse_mass.resize(atom->nmax);
  contact_mass.fill(inverse_mass.data());
  comm_what = COMM_MASS;
  comm->forward_comm(this);
}

// Loads start from the walls' films (computed in their pre_force) for owned atoms, 0 elsewhere.
void PairLubricatedSpringDashpot::begin_film_budget()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (static_cast<int>(load_of_atom.size()) < nall) {
    load_of_atom.resize(atom->nmax);
    scale_of_atom.resize(atom->nmax);
  }
  std::fill(load_of_atom.begin(), load_of_atom.begin() + nall, 0.0);
  for (auto wall : walls)
    wall->add_film_loads(load_of_atom.data(), nlocal);
  nrecord = 0;
}

// A vector of exactly `size` elements (resize alone would at least double its capacity).
template <class T> static void resize_exactly(std::vector<T> &v, std::size_t size)
{
  v.reserve(size);
  v.resize(size);
}

// Room for `more` records (at most one per pair of the step's lists), with 1/8 spare: the
// count changes little from step to step, and doubling would hold twice the bed's films.
void PairLubricatedSpringDashpot::reserve_records(int more)
{
  if (nrecord + more <= static_cast<int>(record_i.size()) &&
      (!shear_records || record_shear.size() >= 3 * record_i.size()))
    return;
  const std::size_t need = nrecord + more, size = need + need / 8;
  resize_exactly(record_i, size);
  resize_exactly(record_j, size);
  resize_exactly(record_force, size);
  if (shear_records) resize_exactly(record_shear, 3 * size);
}

// Pass 1's lists grow to 5/4 of what they need (a few regrowths in a run's first step), not to
// twice: the set-up keeps every pair in the film's reach, the steps fewer.
void PairLubricatedSpringDashpot::grow_pair_lists(std::vector<int> &list_i, std::vector<int> &list_j,
                                                  std::vector<int> *list_jj, int need)
{
  const std::size_t size = need + need / 4;
  resize_exactly(list_i, size);
  resize_exactly(list_j, size);
  if (list_jj) resize_exactly(*list_jj, size);
}

// Loads summed on the owners, scales sent to the ghosts, then every film whose atoms are over
// budget is scaled down by 1 / max(1, D_i, D_j) (lubricated/film_budget.h).
void PairLubricatedSpringDashpot::finish_film_budget()
{
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  if (newton_pair) {
    comm_what = COMM_LOAD;
    comm->reverse_comm(this);
  }
  double *load = load_of_atom.data(), *scale = scale_of_atom.data();
  // An atom no contact moves is not part of the state the budget protects: its load limits
  // nothing (its partners' own loads count their shares of these films).
  const double *held = inverse_mass_on ? inverse_mass.data() : nullptr;
  int over = 0;
  for (int i = 0; i < nlocal; i++) {
    scale[i] = (held && held[i] == 0.0) ? 1.0 : lub::film_scale_of_load(load[i]);
    over |= scale[i] < 1.0;
  }
  // Most steps of most beds leave every film whole: then no scales travel and nothing is redone.
  int any_over = 0;
  MPI_Allreduce(&over, &any_over, 1, MPI_INT, MPI_MAX, world);
  if (!any_over) return;
  comm_what = COMM_SCALE;
  comm->forward_comm(this);
  double **x = atom->x, **f = atom->f;
  if (shear_records) {
    finish_shear_film_budget();
    return;
  }
  for (int r = 0; r < nrecord; r++) {
    const int i = record_i[r], j = record_j[r];
    const double s = std::min(scale[i], scale[j]);
    if (s == 1.0) continue;
    const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
    const double fpair = (s - 1.0) * record_force[r] / std::sqrt(delx * delx + dely * dely + delz * delz);
    f[i][0] += delx * fpair;
    f[i][1] += dely * fpair;
    f[i][2] += delz * fpair;
    if (newton_pair || j < nlocal) {
      f[j][0] -= delx * fpair;
      f[j][1] -= dely * fpair;
      f[j][2] -= delz * fpair;
    }
    if (evflag) ev_tally(i, j, nlocal, newton_pair, 0.0, 0.0, fpair, delx, dely, delz);
  }
}

// The correction pass with shear films: per record, (s - 1) times the normal film along n and the
// shear film at the contact points, with its torques -R_i n x f and -R_j n x f (tangential.h).
void PairLubricatedSpringDashpot::finish_shear_film_budget()
{
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double *scale = scale_of_atom.data(), *radius = atom->radius;
  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  for (int r = 0; r < nrecord; r++) {
    const int i = record_i[r], j = record_j[r];
    const double s = std::min(scale[i], scale[j]);
    if (s == 1.0) continue;
    const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
    const double rinv = 1.0 / std::sqrt(delx * delx + dely * dely + delz * delz);
    const double fpair = (s - 1.0) * record_force[r] * rinv;
    const double *shear = &record_shear[3 * r];
    const lub::Vec3 df{(s - 1.0) * shear[0], (s - 1.0) * shear[1], (s - 1.0) * shear[2]};
    const lub::Vec3 nxf = lub::cross(lub::Vec3{delx * rinv, dely * rinv, delz * rinv}, df);
    const double fx = delx * fpair + df.x, fy = dely * fpair + df.y, fz = delz * fpair + df.z;
    const double radi = radius[i], radj = radius[j];
    f[i][0] += fx;
    f[i][1] += fy;
    f[i][2] += fz;
    torque[i][0] -= radi * nxf.x;
    torque[i][1] -= radi * nxf.y;
    torque[i][2] -= radi * nxf.z;
    if (newton_pair || j < nlocal) {
      f[j][0] -= fx;
      f[j][1] -= fy;
      f[j][2] -= fz;
      torque[j][0] -= radj * nxf.x;
      torque[j][1] -= radj * nxf.y;
      torque[j][2] -= radj * nxf.z;
    }
    if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
  }
}

// The wall fixes of the plugin (at each set-up, after they were initialised): their sustained
// contacts join the check, which a wall whose load exceeds network_check_load turns on.
void PairLubricatedSpringDashpot::find_network_walls()
{
  network_walls.clear();
  network_walls_check = false;
  for (Fix *fix : modify->get_fix_list())
    if (auto *wall = dynamic_cast<FixWallLubricationBase *>(fix)) {
      network_walls.push_back(wall);
      double load, bound;
      lub::network_loads(wall->contact_model(), update->dt, load, bound);
      network_walls_check = network_walls_check || bound > lub::network_check_load;
    }
}

// The network of contacts (lubricated/contact_network.h): per-atom sums over the contacts in
// overlap now and a step ago among the pairs pass 1 kept, then each contact's lower quotient and
// upper row. A lower quotient of 4 or more proves a mode that grows every step: ERROR. Where the
// upper row reaches 4 (stability unproven) and the lower quotient 8/3 (growth likely): WARNING,
// once per run.
void PairLubricatedSpringDashpot::check_contact_network(int ncandidate)
{
  constexpr int nv = lub::network_values;
  double **x = atom->x, **v = atom->v;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, newton_pair = force->newton_pair;
  const double dt = update->dt;
  if (static_cast<int>(network_sums.size()) < nv * nall) network_sums.resize(nv * atom->nmax);
  std::fill(network_sums.begin(), network_sums.begin() + nv * nall, 0.0);
  network_i.clear();
  network_j.clear();
  auto normal = [&](int i, int j, double *n) {
    for (int d = 0; d < 3; d++)
      n[d] = x[i][d] - x[j][d];
    return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  };
  // The masses the contacts move (contact_mass.h): an immovable atom is not part of the state,
  // its infinite mass drops its terms from the sums and quotients.
  const double *inverse = inverse_mass_on ? inverse_mass.data() : nullptr;
  auto mass = [&](int i) { return inverse ? (inverse[i] > 0.0 ? 1.0 / inverse[i] : INFINITY) : rmass[i]; };
  auto pair_mass = [&](int i, int j) {
    return inverse ? lub::reduced_mass_of_inverses(inverse[i], inverse[j]) : lub::reduced_mass(rmass[i], rmass[j]);
  };
  for (int c = 0; c < ncandidate; c++) {
    const int i = candidate_i[c], j = candidate_j[c];
    double n[3];
    const double r = normal(i, j, n), gap = r - radius[i] - radius[j];
    if (!(gap < 0.0) || r == 0.0) continue;
    const double *vi = midpoint ? midpoint->step_velocity(i) : v[i];
    const double *vj = midpoint ? midpoint->step_velocity(j) : v[j];
    for (int d = 0; d < 3; d++)
      n[d] /= r;
    const double u_n = (vi[0] - vj[0]) * n[0] + (vi[1] - vj[1]) * n[1] + (vi[2] - vj[2]) * n[2];
    if (!(gap - u_n * dt < 0.0)) continue;    // in overlap a step ago too
    const int t = index(type[i], type[j]);
    const double m_e = pair_mass(i, j);
    if (m_e == 0.0) continue;    // two immovable atoms
    lub::add_network_contact(&network_sums[nv * i], network_load[t], network_bound[t], m_e, n);
    if (newton_pair || j < nlocal)
      lub::add_network_contact(&network_sums[nv * j], network_load[t], network_bound[t], m_e, n);
    network_i.push_back(i);
    network_j.push_back(j);
  }
  comm_what = COMM_NETWORK;
  if (newton_pair) comm->reverse_comm(this);
  // The walls' sustained contacts (their last evaluation's, by atom ID): a partner of infinite
  // mass, on the owned atom's sums alone, before they go to the ghosts.
  network_wall_contacts.clear();
  std::vector<double> wall_load(network_walls.size()), wall_bound(network_walls.size());
  std::unordered_map<tagint, int> owned;
  for (std::size_t w = 0; w < network_walls.size(); w++) {
    lub::network_loads(network_walls[w]->contact_model(), dt, wall_load[w], wall_bound[w]);
    const auto &records = network_walls[w]->sustained_contacts();
    if (!records.empty() && owned.empty())
      for (int i = 0; i < nlocal; i++)
        owned.emplace(atom->tag[i], i);
    for (const auto &record : records) {
      const auto found = owned.find(record.tag);
      if (found == owned.end() || !std::isfinite(mass(found->second))) continue;    // moved on; immovable
      const int i = found->second;
      lub::add_network_contact(&network_sums[nv * i], wall_load[w], wall_bound[w], mass(i), record.n);
      network_wall_contacts.push_back({i, static_cast<int>(w), {record.n[0], record.n[1], record.n[2]}});
    }
  }
  comm->forward_comm(this);

  // Each contact's bounds; the worst over all ranks decides (contact_network_ranks.h). A wall
  // contact has no second sphere: zero sums and an infinite mass drop its terms.
  lub::NetworkScores scores(comm->me);
  const double no_sums[nv] = {};
  const int npairs = static_cast<int>(network_i.size());
  for (std::size_t k = 0; k < network_wall_contacts.size(); k++) {
    const WallContact &c = network_wall_contacts[k];
    const double *si = &network_sums[nv * c.i];
    scores.add(npairs + static_cast<int>(k),
               lub::network_lower_quotient(wall_load[c.wall], mass(c.i), c.n, si, mass(c.i), no_sums, INFINITY),
               lub::network_upper_row(wall_bound[c.wall], mass(c.i), si, mass(c.i), no_sums, INFINITY),
               wall_bound[c.wall]);
  }
  for (std::size_t k = 0; k < network_i.size(); k++) {
    const int i = network_i[k], j = network_j[k], t = index(type[i], type[j]);
    double n[3];
    const double r = normal(i, j, n);
    for (int d = 0; d < 3; d++)
      n[d] /= r;
    const double m_e = pair_mass(i, j);
    const double *si = &network_sums[nv * i], *sj = &network_sums[nv * j];
    scores.add(static_cast<int>(k), lub::network_lower_quotient(network_load[t], m_e, n, si, mass(i), sj, mass(j)),
               lub::network_upper_row(network_bound[t], m_e, si, mass(i), sj, mass(j)), network_bound[t]);
  }
  lub::NetworkFinding found;
  // A wall contact is described as the atom and "type" -(w + 1), the wall fix's place in
  // network_walls (the finding sorts the types: it comes first).
  auto describe = [&](int k, int *types, long long *tags, double *contacts) {
    if (k >= npairs) {
      const WallContact &c = network_wall_contacts[k - npairs];
      types[0] = type[c.i], types[1] = -(c.wall + 1);
      tags[0] = static_cast<long long>(atom->tag[c.i]), tags[1] = 0;
      contacts[0] = network_sums[nv * c.i + nv - 1], contacts[1] = 0.0;
      return;
    }
    const int ij[2] = {network_i[k], network_j[k]};
    for (int s = 0; s < 2; s++) {
      types[s] = type[ij[s]];
      tags[s] = static_cast<long long>(atom->tag[ij[s]]);
      contacts[s] = network_sums[nv * ij[s] + nv - 1];
    }
  };
  if (!scores.decide(world, network_warned, describe, found)) return;
  std::string message;
  if (found.type_i < 0) {
    const FixWallLubricationBase *wall = network_walls[-found.type_i - 1];
    message = lub::network_message(STYLE, wall->coefficients(), update->dt, found, false,
                                   fmt::format("the walls of fix {} ({})", wall->id, wall->style));
  } else {
    message = lub::network_message(STYLE, coeffs[index(found.type_i, found.type_j)], update->dt, found);
  }
  if (found.unstable) error->all(FLERR, message);
  if (comm->me == 0) error->warning(FLERR, message);
}

// Communication of the bed's per-atom sums (film loads and scales, inverse masses, network sums).
int PairLubricatedSpringDashpot::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  if (comm_what == COMM_NETWORK) {
    constexpr int nv = lub::network_values;
    for (int k = 0; k < n; k++)
      std::copy_n(&network_sums[nv * list[k]], nv, buf + nv * k);
    return nv * n;
  }
  const double *values = comm_what == COMM_MASS ? inverse_mass.data() : scale_of_atom.data();
  for (int k = 0; k < n; k++)
    buf[k] = values[list[k]];
  return n;
}

void PairLubricatedSpringDashpot::unpack_forward_comm(int n, int first, double *buf)
{
  if (comm_what == COMM_NETWORK) {
    std::copy_n(buf, lub::network_values * n, &network_sums[lub::network_values * first]);
    return;
  }
  double *values = comm_what == COMM_MASS ? inverse_mass.data() : scale_of_atom.data();
  for (int k = 0; k < n; k++)
    values[first + k] = buf[k];
}

int PairLubricatedSpringDashpot::pack_reverse_comm(int n, int first, double *buf)
{
  if (comm_what == COMM_NETWORK) {
    std::copy_n(&network_sums[lub::network_values * first], lub::network_values * n, buf);
    return lub::network_values * n;
  }
  for (int k = 0; k < n; k++)
    buf[k] = load_of_atom[first + k];
  return n;
}

void PairLubricatedSpringDashpot::unpack_reverse_comm(int n, int *list, double *buf)
{
  if (comm_what == COMM_NETWORK) {
    constexpr int nv = lub::network_values;
    for (int k = 0; k < n; k++)
      for (int q = 0; q < nv; q++)
        network_sums[nv * list[k] + q] += buf[nv * k + q];
    return;
  }
  for (int k = 0; k < n; k++)
    load_of_atom[list[k]] += buf[k];
}
