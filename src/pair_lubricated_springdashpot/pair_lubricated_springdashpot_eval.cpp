/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot: the pair loops (eval and its vectorised passes); each
   contact is lubricated/contact.h's
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"
#include "vector_forces.h"
#include "vector_pairs.h"

#include "fix_contact_history/fix_contact_history.h"
#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_step_velocity/fix_step_velocity.h"
#include "lubricated/film_budget.h"
#include "lubricated/overlap_check.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace LAMMPS_NS;
namespace lub = lubricated;

// A pair outside distance `outer` (squared: outer_sq) comes within it during the coming step
// at most if gap < reach + |u_n| dt, i.e. rsq - |dv.del| dt < outer r, tested without a sqrt.
static inline bool within_a_step(double rsq, double dv_dot_del, double dt, double outer_sq)
{
  const double s = rsq - std::fabs(dv_dot_del) * dt;
  return (s <= 0.0) | (s * s < outer_sq * rsq);
}

// Per owned or ghost atom, its radius grown by how far it can move in the coming step (|v|_1 dt
// >= |v| dt): the pairs that can close their gap within the step are within the sum of both
// grown radii. One array for pass 1 to read, not two.
void PairLubricatedSpringDashpot::update_step_reach(double **v)
{
  const double dt = update->dt;
  const double *radius = atom->radius;
  const int nall = atom->nlocal + atom->nghost;
  if (static_cast<int>(loop_lists.step_reach.size()) < nall) loop_lists.step_reach.resize(atom->nmax);
  double *out = loop_lists.step_reach.data();
  if (nall == 0) return;    // no atoms: maybe no velocity array
  // The velocities as the block they are (3 per atom, or the midpoint integrator's rows): a loop
  // the compiler vectorises.
  const double *__restrict vb = midpoint ? midpoint->step_velocities() : v[0];
  const int w = midpoint ? FixNVESphereMidpoint::step_velocity_stride() : 3;
  for (int k = 0; k < nall; k++)
    out[k] = radius[k] + (std::fabs(vb[w * k]) + std::fabs(vb[w * k + 1]) + std::fabs(vb[w * k + 2])) * dt;
}

// Pass 1, branch-free: keep the list entries that can act within the coming step: in the
// film's reach (the largest of the two types) or in contact, or within what both atoms can
// move in a step. With friction, entries holding an elongation to forget are kept too (never
// film-only: the whole contact forgets it).
// Whether an entry is kept follows no pattern a branch predictor could learn, hence no branch.
// SPLIT: entries apart by more than both atoms can move in the step (no contact can start) but
// in the film's reach go to the film-only list instead. Returns the candidates' count; nfilm:
// the film-only list's (SPLIT), or how many of the candidates would go there (for compute pair).
// In pieces: from list entry `next` on, stopping before an atom whose entries could take either
// list past `limit` (each piece goes to pass 2 while its atoms are in the cache, and the lists
// hold one piece, not the step's pairs); `next` is left at the first atom not selected.
// UNIFORM_REACH: one film reach for every type pair (film_reach_uniform; no type per entry).
template <bool WET, bool TANGENTIAL, bool SPLIT, bool UNIFORM_REACH>
int PairLubricatedSpringDashpot::select_pairs(int &next, int &nfilm, int limit)
{
  const double *x = atom->x[0];                          // positions, 3 per atom (one block)
  const double *grown = loop_lists.step_reach.data();    // grown radii (update_step_reach)
  const int *type = atom->type;
  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  const double *reach_table = max_reach.data();
  const int stride = ntypes_alloc + 1;
  const double reach_all = reach_table[stride + 1];
  // The counts in locals: the reference nfilm, which the lists' stores might alias, would keep
  // its count in memory, a store-to-load chain through every entry.
  // 64-bit: indices without a sign extension per entry.
  std::ptrdiff_t ncandidate = 0, nfilm_here = 0;
  int ii = next;
  for (; ii < inum; ii++) {
    const int i = ilist[ii];
    const int jnum = numneigh[i];
    if ((ncandidate + jnum > limit || nfilm_here + jnum > limit) && ncandidate + nfilm_here > 0) break;
    const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
    const double radi_moved = grown[i];
    const double *reach_row = reach_table + type[i] * stride;
    const int *jlist = firstneigh[i];
    const char *touched = TANGENTIAL && history ? history->touched(i) : nullptr;
    // candidate_jj only grows with friction: a run that adds friction finds it shorter.
    if (ncandidate + jnum > static_cast<int>(loop_lists.candidate_i.size()) ||
        (TANGENTIAL && loop_lists.candidate_jj.size() < loop_lists.candidate_i.size()))
      grow_pair_lists(loop_lists.candidate_i, loop_lists.candidate_j, TANGENTIAL ? &loop_lists.candidate_jj : nullptr,
                      ncandidate + jnum);
    if (WET && SPLIT && nfilm_here + jnum > static_cast<int>(loop_lists.film_i.size()))
      grow_pair_lists(loop_lists.film_i, loop_lists.film_j, nullptr, nfilm_here + jnum);
    int *out_i = loop_lists.candidate_i.data(), *out_j = loop_lists.candidate_j.data(),
        *out_jj = loop_lists.candidate_jj.data();
    int *film_out_i = loop_lists.film_i.data(), *film_out_j = loop_lists.film_j.data();
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double *xj = x + 3 * static_cast<std::size_t>(j);
      const double delx = xi - xj[0];
      const double dely = yi - xj[1];
      const double delz = zi - xj[2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double touch = radi_moved + grown[j];
      const double near = touch + (WET ? (UNIFORM_REACH ? reach_all : reach_row[type[j]]) : 0.0);
      out_i[ncandidate] = i;
      out_j[ncandidate] = j;
      if (TANGENTIAL) out_jj[ncandidate] = jj;
      int keep = rsq < (SPLIT ? touch * touch : near * near);
      if (TANGENTIAL && touched) keep |= touched[jj] != 0;    // the flag is 1 or 2 (lubricated::history_flag)
      if (WET && SPLIT) {
        film_out_i[nfilm_here] = i;
        film_out_j[nfilm_here] = j;
        nfilm_here += (rsq < near * near) & !keep;
      } else if (WET) {
        nfilm_here += keep & !(rsq < touch * touch) & !(TANGENTIAL && touched && touched[jj]);
      }
      ncandidate += keep;
    }
  }
  next = ii;
  nfilm = static_cast<int>(nfilm_here);
  return static_cast<int>(ncandidate);
}

// Whether a pair among this piece's candidates overlaps by more than overlap_depth of the smaller
// radius (such a pair is in contact, hence a candidate): a branch-free scan, on the steps the
// check is due (overlap_check_interval) so that other steps pay nothing for it.
bool PairLubricatedSpringDashpot::any_deep_overlap(int ncandidate) const
{
  const double *x = atom->x[0], *radius = atom->radius;
  const int *ci = loop_lists.candidate_i.data(), *cj = loop_lists.candidate_j.data();
  const double depth = overlap_depth;
  int deep = 0;
  for (int c = 0; c < ncandidate; c++) {
    const int i = ci[c], j = cj[c];
    const double dx = x[3 * i] - x[3 * j], dy = x[3 * i + 1] - x[3 * j + 1], dz = x[3 * i + 2] - x[3 * j + 2];
    const double within = lub::overlap_distance(radius[i], radius[j], depth);
    deep |= dx * dx + dy * dy + dz * dz < within * within;
  }
  return deep != 0;
}

// A pair among this piece's candidates overlaps by more than overlap_depth of the smaller
// radius: the deepest pair of movable atoms as a WARNING, once per run for each of the two
// limits (after the first, only overlaps beyond the second are looked for).
__attribute__((noinline)) void PairLubricatedSpringDashpot::check_pair_overlaps(int ncandidate)
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const double *inverse = inverse_mass_on ? inverse_mass.data() : nullptr;
  int deepest = -1;
  double largest = 0.0, deepest_gap = 0.0;
  for (int c = 0; c < ncandidate; c++) {
    const int i = loop_lists.candidate_i[c], j = loop_lists.candidate_j[c];
    if (inverse && inverse[i] == 0.0 && inverse[j] == 0.0) continue;    // neither can move
    const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
    const double gap = std::sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]) - radius[i] - radius[j];
    const double fraction = lub::overlap_fraction(gap, std::min(radius[i], radius[j]));
    if (fraction > largest) largest = fraction, deepest = c, deepest_gap = gap;
  }
  if (deepest < 0 || lub::overlap_level(largest) == lub::OverlapLevel::none) return;
  const int i = loop_lists.candidate_i[deepest], j = loop_lists.candidate_j[deepest];
  const int ti = atom->type[i], tj = atom->type[j];
  const std::string who = fmt::format("Pair style lubricated/springdashpot: atoms {} and {} (types {} {})",
                                      atom->tag[i], atom->tag[j], ti, tj);
  const std::string text = lub::overlap_message(who, deepest_gap, std::min(radius[i], radius[j]), largest,
                                                coeffs[index(ti, tj)], update->dt, false);
  // A pair warns, beyond either limit once per run: a sphere deep in a partner is not lost (dense
  // 1:10 beds overlap so and stay stable, the network check guards them), a sphere through a
  // wall is (the walls' ERROR).
  const bool beyond_error = lub::overlap_level(largest) == lub::OverlapLevel::error;
  if (beyond_error ? overlap_deep_warned : overlap_warned) return;
  overlap_warned = true;
  overlap_deep_warned = beyond_error;
  overlap_depth = lub::overlap_error_fraction;
  error->warning(FLERR, "{}", text);
}

// A pair that is not in contact now has no elongation to keep.
inline void PairLubricatedSpringDashpot::forget_history(int i, int jj)
{
  char &touched = history->touched(i)[jj];
  if (touched) {
    touched = 0;
    double *h = history->values(i) + 3 * jj;
    h[0] = h[1] = h[2] = 0.0;
  }
}

// What the whole contact reads beyond the normal direction (with friction, rolling or a shear
// film): the slip from the engine's velocities (under the midpoint integrator V~, not the step
// velocity of the normal contact), the spheres, and the history's slot.
inline void PairLubricatedSpringDashpot::set_tangential_point(const PairLoop &loop, int i, int j, int jj,
                                                              const lub::ContactModel &model, lub::ContactPoint &p,
                                                              lub::HistorySlot &slot)
{
  double **v = loop.v;
  const double *inverse = loop.inverse;
  const double radi = loop.radius[i], radj = loop.radius[j];
  p.dv = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
  p.omega_i = {loop.omega[i][0], loop.omega[i][1], loop.omega[i][2]};
  p.omega_j = {loop.omega[j][0], loop.omega[j][1], loop.omega[j][2]};
  p.radius_i = radi, p.radius_j = radj;
  p.reduced_radius = radi * radj / (radi + radj);
  // An added mass moves with the spheres, not with their turning (contact_mass.h).
  if (inverse && contact_mass.carries_added_mass())
    p.tangential_mass = lub::tangential_mass_of_sides(inverse[i], loop.rmass[i], inverse[j], loop.rmass[j]);
  if ((p.gap < 0.0 && model.tangential.rolling_active()) || model.tangential.roll_film_active()) {
    // The spheres' own inertia (also in a rigid body); an immovable atom does not turn.
    p.mass_i = inverse && inverse[i] == 0.0 ? 0.0 : loop.rmass[i];
    p.mass_j = inverse && inverse[j] == 0.0 ? 0.0 : loop.rmass[j];
  }
  if (history) slot = lub::history_slot(history->values(i) + 3 * jj, history->touched(i)[jj], loop.steps);
}

// The pair's whole force (fx, fy, fz) on i, the opposite on j, and its tallies.
template <bool TANGENTIAL>
inline void PairLubricatedSpringDashpot::apply_pair_force(const PairLoop &loop, int i, int j, const double *del,
                                                          double fpair, const lub::Vec3 &tangential, double energy)
{
  double **f = loop.f;
  const int nlocal = loop.nlocal, newton_pair = loop.newton_pair;
  const double fx = del[0] * fpair + tangential.x, fy = del[1] * fpair + tangential.y,
               fz = del[2] * fpair + tangential.z;
  f[i][0] += fx;
  f[i][1] += fy;
  f[i][2] += fz;
  if (newton_pair || j < nlocal) {
    f[j][0] -= fx;
    f[j][1] -= fy;
    f[j][2] -= fz;
  }
  if (evflag) {
    if (TANGENTIAL)
      ev_tally_xyz(i, j, nlocal, newton_pair, energy, 0.0, fx, fy, fz, del[0], del[1], del[2]);
    else
      ev_tally(i, j, nlocal, newton_pair, energy, 0.0, fpair, del[0], del[1], del[2]);
  }
}

// The whole contact of a pair at its contact point p (normal direction del * rinv), the film
// budget's records, the torques, forces and tallies.
template <bool WET, bool TANGENTIAL>
inline void PairLubricatedSpringDashpot::contact(const PairLoop &loop, int i, int j, int jj,
                                                 const lub::ContactModel &model, lub::ContactPoint &p,
                                                 const double *del, double rinv)
{
  const int nlocal = loop.nlocal, newton_pair = loop.newton_pair;
  const double kick_time = loop.kick_time;
  const bool records = WET && loop.budget;
  // Without tangential parts the normal force alone (a whole ContactForces would cost a zero
  // fill per pair).
  lub::NormalForce fn;
  double share = 0.0;
  lub::Vec3 tangential;
  if constexpr (TANGENTIAL) {
    lub::HistorySlot slot;
    p.n = {del[0] * rinv, del[1] * rinv, del[2] * rinv};
    set_tangential_point(loop, i, j, jj, model, p, slot);
    const lub::ContactForces c = lub::contact_forces<true>(model, p, slot, loop.when);
    fn = c.normal;
    if (history) history->touched(i)[jj] = static_cast<char>(lub::history_flag(slot));
    if (records) share = lub::film_share(fn.lubrication, p.reduced_mass, p.u_n, kick_time);
    if (records && budget.records_shear())
      budget.record_films(i, j, fn.lubrication, c.shear, lub::contact_film_share(share, c.shear_share(kick_time)),
                          nlocal, newton_pair, c.roll_film);
    tangential = c.tangential;
    loop.torque[i][0] += c.torque_i.x, loop.torque[i][1] += c.torque_i.y, loop.torque[i][2] += c.torque_i.z;
    if (newton_pair || j < nlocal)
      loop.torque[j][0] += c.torque_j.x, loop.torque[j][1] += c.torque_j.y, loop.torque[j][2] += c.torque_j.z;
  } else {
    fn = lub::normal_force(model.normal, p.gap, p.film, p.reduced_mass, p.u_n, loop.when);
    if (records) share = lub::film_share(fn.lubrication, p.reduced_mass, p.u_n, kick_time);
  }
  if (records && !(TANGENTIAL && budget.records_shear()))
    budget.record_film(i, j, fn.lubrication, share, nlocal, newton_pair);
  apply_pair_force<TANGENTIAL>(loop, i, j, del, fn.total() * rinv, tangential, fn.energy);
}

// Pass 2: one pair kept by pass 1 (jj, its place in i's neighbor list, for the history only):
// the whole contact (lubricated/contact.h), the film budget's records, forces, torques, tallies.
template <bool WET, bool TANGENTIAL>
inline void PairLubricatedSpringDashpot::evaluate_pair(const PairLoop &loop, const int i, const int j, const int jj)
{
  double **x = loop.x, **v = loop.v;
  const double *radius = loop.radius, *rmass = loop.rmass, *inverse = loop.inverse;
  const double dt = loop.dt;
  const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
  const double delx = del[0], dely = del[1], delz = del[2];
  const double rsq = delx * delx + dely * dely + delz * delz;
  const double radsum = radius[i] + radius[j];
  const lub::ContactModel &model = loop.models[loop.type[i] * loop.stride + loop.type[j]];
  auto forget = [&]() {
    if (TANGENTIAL && history) forget_history(i, jj);
  };

  const double *vi = v[i], *vj = v[j];
  if (midpoint && model.normal.exact) vi = midpoint->step_velocity(i), vj = midpoint->step_velocity(j);
  const double dvx = vi[0] - vj[0], dvy = vi[1] - vj[1], dvz = vi[2] - vj[2];

  lub::ContactPoint p;
  double reach = 0.0;
  if (WET && model.normal.lubrication.active()) {
    p.film = lub::film_radius_pair(radius[i], radius[j]);
    reach = model.normal.reach(p.film.value);
  }
  const double outer = radsum + reach;
  if (rsq >= outer * outer) {
    // Apart and out of this pair's film (pass 1 used the types' largest): only a contact
    // starting or ending, or a film entered or left, within a step can act (a contact that
    // ended within the last step releases its spring: contact_forces forgets it then).
    if (!model.normal.exact || !within_a_step(rsq, dvx * delx + dvy * dely + dvz * delz, dt, outer * outer)) {
      forget();
      return;
    }
  }
  if (rsq == 0.0) {    // coincident centres: no normal direction is defined
    forget();
    return;
  }

  const double r = std::sqrt(rsq);
  const double rinv = 1.0 / r;
  p.gap = r - radsum;
  p.u_n = (dvx * delx + dvy * dely + dvz * delz) * rinv;
  p.reduced_mass =
      inverse ? lub::reduced_mass_of_inverses(inverse[i], inverse[j]) : lub::reduced_mass(rmass[i], rmass[j]);
  if (p.reduced_mass == 0.0) {    // neither atom can move (the vectorised loops give such pairs 0)
    forget();
    return;
  }
  contact<WET, TANGENTIAL>(loop, i, j, jj, model, p, del, rinv);
}

// One film reach for every type pair: pass 1 then looks up no types.
void PairLubricatedSpringDashpot::find_uniform_film_reach()
{
  const int stride = ntypes_alloc + 1;
  film_reach_uniform = true;
  for (int a = 1; a < stride; a++)
    for (int b = 1; b < stride; b++)
      film_reach_uniform = film_reach_uniform && max_reach[a * stride + b] == max_reach[stride + 1];
}

// What every pair of this evaluation reads. Full-step velocities at a run start, used by each
// integrator its own way (contact_step.h).
PairLubricatedSpringDashpot::PairLoop PairLubricatedSpringDashpot::pair_loop(double **v, bool wet) const
{
  PairLoop loop;
  loop.x = atom->x, loop.v = v, loop.f = atom->f, loop.torque = atom->torque;
  loop.omega = continued ? step_velocity->spin() : atom->omega;
  loop.radius = atom->radius, loop.rmass = atom->rmass, loop.inverse = inverse_mass_on ? inverse_mass.data() : nullptr;
  loop.type = atom->type;
  loop.models = models.data(), loop.stride = ntypes_alloc + 1;
  loop.nlocal = atom->nlocal, loop.newton_pair = force->newton_pair;
  loop.dt = update->dt;
  const lub::EvaluationKind kind =
      lub::evaluation_kind(loop.dt, update->setupflag != 0, continued, midpoint != nullptr);
  loop.when = kind.when, loop.kick_time = kind.kick_time;
  loop.budget = wet && budget.active();
  loop.steps = !update->setupflag;
  return loop;
}

template <bool WET, bool TANGENTIAL, bool SPLIT> void PairLubricatedSpringDashpot::eval()
{
  // The velocities of the last step: the engine's, or in a set-up that continues the last run
  // the ones it restored (fix_step_velocity.h).
  double **v = continued ? step_velocity->velocity() : atom->v;
  update_step_reach(v);
  // The contact-network check reads the step's candidates at once: on its steps pass 1 selects
  // the whole list in one piece, which stays for check_network.
  const bool network_due = network.due();
  const int limit = network_due ? std::numeric_limits<int>::max() : pairs_per_piece;
  if (WET)
    find_uniform_film_reach();
  else
    film_reach_uniform = true;
  const PairLoop loop = pair_loop(v, WET);
  auto evaluate = [ this, loop ](int i, int j, int jj) __attribute__((always_inline))
  {
    evaluate_pair<WET, TANGENTIAL>(loop, i, j, jj);
  };

  int next = 0;
  do {
    int nfilm;
    const int ncandidate = film_reach_uniform ? select_pairs<WET, TANGENTIAL, SPLIT, true>(next, nfilm, limit)
                                              : select_pairs<WET, TANGENTIAL, SPLIT, false>(next, nfilm, limit);
    selected_pairs += ncandidate + (SPLIT ? nfilm : 0);
    film_only_pairs += nfilm;
    if (!SPLIT) nfilm = 0;                               // counted only: no film-only list
    if (network_due) network_candidates = ncandidate;    // checked after the films (check_network)
    if (overlap_check_due && !overlap_deep_warned && any_deep_overlap(ncandidate)) check_pair_overlaps(ncandidate);
    if (loop.budget) budget.reserve_records(ncandidate + nfilm);
    if constexpr (SPLIT && !TANGENTIAL) {
      vector_forces<false>(ncandidate, nfilm, v, loop.omega, evaluate);
      continue;
    }
    // With friction or rolling: the film-only pairs (normal and shear film) and, in steps, the
    // sustained frictional contacts vectorised, the rest through the whole contact.
    if constexpr (SPLIT) {
      if (loop.steps) {
        vector_forces<true>(ncandidate, nfilm, v, loop.omega, evaluate);
        continue;
      }
      vector_forces<true>(0, nfilm, v, loop.omega, evaluate);
    }
    for (int c = 0; c < ncandidate; c++)
      evaluate(loop_lists.candidate_i[c], loop_lists.candidate_j[c], TANGENTIAL ? loop_lists.candidate_jj[c] : 0);
  } while (next < list->inum);
}

// The loops compute() runs: one per combination (a scene pays only for what it uses).
template void PairLubricatedSpringDashpot::eval<true, true>();
template void PairLubricatedSpringDashpot::eval<true, true, true>();
template void PairLubricatedSpringDashpot::eval<false, true>();
template void PairLubricatedSpringDashpot::eval<false, true, true>();
template void PairLubricatedSpringDashpot::eval<true, false>();
template void PairLubricatedSpringDashpot::eval<false, false>();
template void PairLubricatedSpringDashpot::eval<true, false, true>();
template void PairLubricatedSpringDashpot::eval<false, false, true>();
