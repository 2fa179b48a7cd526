/* ----------------------------------------------------------------------
   The contact-network check of pair_style lubricated/springdashpot (contact_network_check.h)
------------------------------------------------------------------------- */

#include "contact_network_check.h"

#include "film_budget/atom_vector_comm.h"
#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "lubricated/contact_network.h"
#include "lubricated/contact_network_message.h"
#include "lubricated/contact_network_ranks.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

using namespace LAMMPS_NS;
namespace lub = lubricated;

void ContactNetworkCheck::allocate(int ntypes)
{
  stride = ntypes + 1;
  load.assign(stride * stride, 0.0);
  bound.assign(stride * stride, 0.0);
}

void ContactNetworkCheck::start_run()
{
  on = warned = false;
  next = 0;
}

// Load of a sustained contact of these types (contact_network.h): kappa + 2 gamma of its per-step
// constants, and the larger of it and the tangential spring's (friction) for the upper bound.
void ContactNetworkCheck::set_loads(int i, int j, const lub::ContactModel &model)
{
  double l, b;
  lub::network_loads(model, update->dt, l, b);
  load[i * stride + j] = load[j * stride + i] = l;
  bound[i * stride + j] = bound[j * stride + i] = b;
  on = on || b > lub::network_check_load;
}

void ContactNetworkCheck::find_participants()
{
  participants.clear();
  participants_on = false;
  for (Fix *fix : modify->get_fix_list())
    if (auto *contacts = dynamic_cast<ContactNetworkParticipant *>(fix)) {
      participants.push_back({contacts, fix});
      double l, b;
      lub::network_loads(contacts->contact_model(), update->dt, l, b);
      participants_on = participants_on || b > lub::network_check_load;
    }
}

bool ContactNetworkCheck::due()
{
  const bool now = (on || participants_on) && !update->setupflag && update->ntimestep >= next;
  if (now) next = update->ntimestep + lub::network_check_interval;
  return now;
}

// The masses the contacts move (contact_mass.h): an immovable atom is not part of the state,
// its infinite mass drops its terms from the sums and quotients.
double ContactNetworkCheck::mass(const Pairs &pairs, int i) const
{
  const double *inverse = pairs.inverse_mass;
  return inverse ? (inverse[i] > 0.0 ? 1.0 / inverse[i] : INFINITY) : atom->rmass[i];
}

double ContactNetworkCheck::pair_mass(const Pairs &pairs, int i, int j) const
{
  const double *inverse = pairs.inverse_mass;
  return inverse ? lub::reduced_mass_of_inverses(inverse[i], inverse[j])
                 : lub::reduced_mass(atom->rmass[i], atom->rmass[j]);
}

// The unit normal from j to i, and the distance.
static double unit_normal(double **x, int i, int j, double *n)
{
  for (int d = 0; d < 3; d++)
    n[d] = x[i][d] - x[j][d];
  const double r = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return r;
}

// The network (lubricated/contact_network.h): per-atom sums over the contacts in overlap now and a
// step ago, then each contact's lower quotient and upper row. A lower quotient of 4 or more proves
// a mode that grows every step: ERROR. Where the upper row reaches 4 (stability unproven) and the
// lower quotient 8/3 (growth likely): WARNING, once per run.
void ContactNetworkCheck::check(const Pairs &pairs)
{
  const int nall = atom->nlocal + atom->nghost;
  constexpr int nv = lub::network_values;
  if (static_cast<int>(sums.size()) < nv * nall) sums.resize(nv * atom->nmax);
  std::fill(sums.begin(), sums.begin() + nv * nall, 0.0);
  find_solved_films(pairs);
  sum_pair_contacts(pairs);
  if (force->newton_pair) exchange.reverse(sums.data(), nv);
  sum_wall_contacts(pairs);
  exchange.forward(sums.data(), nv);
  score_and_report(pairs);
}

// The sustained pair contacts among the candidates, on both atoms' sums.
void ContactNetworkCheck::sum_pair_contacts(const Pairs &pairs)
{
  constexpr int nv = lub::network_values;
  double **x = atom->x, **v = atom->v;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const double dt = update->dt;
  network_i.clear();
  network_j.clear();
  network_bound.clear();
  network_relief.clear();
  for (int c = 0; c < pairs.n; c++) {
    const int i = pairs.i[c], j = pairs.j[c];
    double n[3];
    const double r = unit_normal(x, i, j, n), gap = r - radius[i] - radius[j];
    if (!(gap < 0.0) || r == 0.0) continue;
    const double *vi = pairs.midpoint ? pairs.midpoint->step_velocity(i) : v[i];
    const double *vj = pairs.midpoint ? pairs.midpoint->step_velocity(j) : v[j];
    for (int d = 0; d < 3; d++)
      n[d] /= r;
    const double u_n = (vi[0] - vj[0]) * n[0] + (vi[1] - vj[1]) * n[1] + (vi[2] - vj[2]) * n[2];
    if (!(gap - u_n * dt < 0.0)) continue;    // in overlap a step ago too
    const int t = type[i] * stride + type[j];
    const double m_e = pair_mass(pairs, i, j);
    if (m_e == 0.0) continue;    // two immovable atoms
    const double own = own_film(i, j), s_bound = relieved_bound(load[t], bound[t], own, m_e);
    lub::add_network_contact(&sums[nv * i], load[t], s_bound, m_e, n);
    if (newton_pair || j < nlocal) lub::add_network_contact(&sums[nv * j], load[t], s_bound, m_e, n);
    network_i.push_back(i);
    network_j.push_back(j);
    network_bound.push_back(s_bound);
    network_relief.push_back(lub::film_relief(own, dt, m_e));
  }
}

// The upper bound's load of a contact relieved by its own solved film of normal damping c (0:
// none; the tangential spring's load, where it bounds, is not relieved); the lower bound's sums
// keep the loads (b_k^T S b_k).
double ContactNetworkCheck::relieved_bound(double load, double bound, double c, double mass) const
{
  if (!(c > 0.0)) return bound;
  const double relieved = lub::film_relieved_load(load, c, update->dt, mass);
  return bound > load ? std::max(relieved, bound) : relieved;
}

// The normal damping of the films the solve took at this step: the pairs' by pair (either
// order), the walls' by atom with their normals (from the wall to the atom).
void ContactNetworkCheck::find_solved_films(const Pairs &pairs)
{
  const long long nall = atom->nlocal + atom->nghost;
  solved_damping.clear();
  solved_wall_films.clear();
  for (int k = 0; k < pairs.solved.count; k++) {
    const lub::FilmLink &link = pairs.solved.links[k];
    if (!(link.normal_damping > 0.0)) continue;
    if (link.j < 0) {
      solved_wall_films.emplace(link.i, WallFilm{{link.normal.x, link.normal.y, link.normal.z}, link.normal_damping});
      continue;
    }
    solved_damping[link.i * nall + link.j] = link.normal_damping;
    solved_damping[link.j * nall + link.i] = link.normal_damping;
  }
}

// The normal damping of the solved wall film of owned atom i along the normal n (0: none).
double ContactNetworkCheck::own_wall_film(int i, const double *n) const
{
  const auto range = solved_wall_films.equal_range(i);
  for (auto film = range.first; film != range.second; ++film) {
    const double *m = film->second.n;
    if (m[0] * n[0] + m[1] * n[1] + m[2] * n[2] > 1.0 - 1e-6) return film->second.damping;
  }
  return 0.0;
}

// The normal damping of pair (i, j)'s film in this step's solve (0: not solved).
double ContactNetworkCheck::own_film(int i, int j) const
{
  if (solved_damping.empty()) return 0.0;
  const auto film = solved_damping.find(static_cast<long long>(i) * (atom->nlocal + atom->nghost) + j);
  return film == solved_damping.end() ? 0.0 : film->second;
}

// The participants' sustained contacts (their last evaluation's, by atom ID): a partner of
// infinite mass, on the owned atom's sums alone, before they go to the ghosts.
void ContactNetworkCheck::sum_wall_contacts(const Pairs &pairs)
{
  constexpr int nv = lub::network_values;
  const int nlocal = atom->nlocal;
  wall_contacts.clear();
  wall_load.assign(participants.size(), 0.0);
  wall_bound.assign(participants.size(), 0.0);
  std::unordered_map<tagint, int> owned;
  for (std::size_t w = 0; w < participants.size(); w++) {
    const ContactNetworkParticipant &wall = *participants[w].contacts;
    lub::network_loads(wall.contact_model(), update->dt, wall_load[w], wall_bound[w]);
    const auto &records = wall.sustained_contacts();
    if (!records.empty() && owned.empty())
      for (int i = 0; i < nlocal; i++)
        owned.emplace(atom->tag[i], i);
    for (const auto &record : records) {
      const auto found = owned.find(record.tag);
      if (found == owned.end() || !std::isfinite(mass(pairs, found->second))) continue;    // moved on; immovable
      const int i = found->second;
      const double m = mass(pairs, i), own = own_wall_film(i, record.n);
      const double s_bound = relieved_bound(wall_load[w], wall_bound[w], own, m);
      lub::add_network_contact(&sums[nv * i], wall_load[w], s_bound, m, record.n);
      wall_contacts.push_back({i,
                               static_cast<int>(w),
                               {record.n[0], record.n[1], record.n[2]},
                               s_bound,
                               lub::film_relief(own, update->dt, m)});
    }
  }
}

// Each contact's bounds; the worst over all ranks decides (contact_network_ranks.h). A wall
// contact has no second sphere: zero sums and an infinite mass drop its terms.
void ContactNetworkCheck::score_and_report(const Pairs &pairs)
{
  constexpr int nv = lub::network_values;
  const int *type = atom->type;
  lub::NetworkScores scores(comm->me);
  const double no_sums[nv] = {};
  const int npairs = static_cast<int>(network_i.size());
  for (std::size_t k = 0; k < wall_contacts.size(); k++) {
    const WallContact &c = wall_contacts[k];
    const double *si = &sums[nv * c.i];
    const double m = mass(pairs, c.i);
    // As for a pair (below), with the wall's own solved film.
    const double lower = lub::network_lower_quotient(wall_load[c.wall], m, c.n, si, m, no_sums, INFINITY) - c.relief;
    scores.add(npairs + static_cast<int>(k), lower, lub::network_upper_row(c.bound, m, si, m, no_sums, INFINITY),
               wall_bound[c.wall]);
  }
  for (int k = 0; k < npairs; k++) {
    const int i = network_i[k], j = network_j[k], t = type[i] * stride + type[j];
    double n[3];
    const double r = unit_normal(atom->x, i, j, n);
    for (int d = 0; d < 3; d++)
      n[d] /= r;
    const double m_e = pair_mass(pairs, i, j), mi = mass(pairs, i), mj = mass(pairs, j);
    const double *si = &sums[nv * i], *sj = &sums[nv * j];
    // The lower bound less the contact's own solved film, 2 a_k (contact_network.h).
    const double lower = lub::network_lower_quotient(load[t], m_e, n, si, mi, sj, mj) - network_relief[k];
    // Per unit of the type pair's load (the advice of the message), the films' relief counted.
    scores.add(k, lower, lub::network_upper_row(network_bound[k], m_e, si, mi, sj, mj), bound[t]);
  }
  lub::NetworkFinding found;
  auto describe_contact = [this](int k, int *types, long long *tags, double *contacts) {
    describe(k, types, tags, contacts);
  };
  if (!scores.decide(world, warned, describe_contact, found)) return;
  std::string message;
  if (found.type_i < 0) {
    const Participant &wall = participants[-found.type_i - 1];
    message = lub::network_message(style, wall.contacts->coefficients(), update->dt, found, false,
                                   fmt::format("the walls of fix {} ({})", wall.fix->id, wall.fix->style));
  } else {
    message = lub::network_message(style, pairs.coeffs[found.type_i * stride + found.type_j], update->dt, found);
  }
  if (found.unstable) error->all(FLERR, message);
  if (comm->me == 0) error->warning(FLERR, message);
}

// Contact k of the last check: a pair's atoms, or a wall contact's atom and "type" -(w + 1), the
// participant's place (the finding sorts the types: it comes first).
void ContactNetworkCheck::describe(int k, int *types, long long *tags, double *contacts) const
{
  constexpr int nv = lub::network_values;
  const int *type = atom->type;
  const int npairs = static_cast<int>(network_i.size());
  if (k >= npairs) {
    const WallContact &c = wall_contacts[k - npairs];
    types[0] = type[c.i], types[1] = -(c.wall + 1);
    tags[0] = static_cast<long long>(atom->tag[c.i]), tags[1] = 0;
    contacts[0] = sums[nv * c.i + nv - 1], contacts[1] = 0.0;
    return;
  }
  const int ij[2] = {network_i[k], network_j[k]};
  for (int s = 0; s < 2; s++) {
    types[s] = type[ij[s]];
    tags[s] = static_cast<long long>(atom->tag[ij[s]]);
    contacts[s] = sums[nv * ij[s] + nv - 1];
  }
}

double ContactNetworkCheck::memory_usage() const
{
  return (network_i.capacity() + network_j.capacity()) * sizeof(int) +
         (load.capacity() + bound.capacity() + sums.capacity() + network_bound.capacity() + network_relief.capacity()) *
             sizeof(double) +
         solved_damping.size() * (sizeof(long long) + sizeof(double) + 2 * sizeof(void *)) +
         solved_wall_films.size() * (sizeof(int) + sizeof(WallFilm) + 2 * sizeof(void *));
}
