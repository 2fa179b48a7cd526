/* -*- c++ -*- ----------------------------------------------------------
   pair_style lubricated/springdashpot: the second pass's vectorised loops (vector_pairs.h), their
   gathers and scatters; included by pair_lubricated_springdashpot_eval.cpp alone (a template
   of the pair loop's general evaluation)
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_VECTOR_FORCES_H
#define LMP_LUBRICATED_VECTOR_FORCES_H

#include "pair_lubricated_springdashpot.h"
#include "vector_pairs.h"

#include "fix_contact_history/fix_contact_history.h"
#include "lubricated/film_budget.h"

#include "atom.h"
#include "force.h"
#include "update.h"

#include <algorithm>
#include <vector>

namespace LAMMPS_NS {

// The vectorised loops (vector_pairs.h) over the film-only list and the kept entries of one
// piece, in chunks that stay in the cache between computing and applying the forces; kept
// entries where a contact starts or ends take a loop of their own where the model has no entry
// loss, else (and where that loop leaves them) the general loop, evaluate(i, j, jj). Unless one
// model serves every pair, each chunk is first grouped by type pair (a counting sort).
// TANGENTIAL (friction or rolling, and maybe a shear film): the film-only list with the shear
// film, and the kept entries of type pairs with friction and without rolling resistance through
// the sustained frictional contact loop, then those it leaves (a contact that starts or ends, a
// new one) through the frictional event loop where the model has no entry loss; the others
// through the general loop. In steps only (the elongation advances).
template <bool TANGENTIAL, class Evaluate> class PairLubricatedSpringDashpot::VectorForces {
  using ContactModel = lubricated::ContactModel;
  static constexpr int chunk = 256;

 public:
  VectorForces(PairLubricatedSpringDashpot &pair, double **v, double **omega, Evaluate &evaluate) :
      pair(pair), evaluate(evaluate), atoms{pair.atom->x[0],
                                            v[0],
                                            pair.atom->radius,
                                            pair.atom->rmass,
                                            pair.inverse_mass_on ? pair.inverse_mass.data() : nullptr,
                                            TANGENTIAL ? omega[0] : nullptr}
  {
  }

  void run(int ncandidate, int nfilm)
  {
    if (TANGENTIAL) {
      run_list(pair.loop_lists.film_i.data(), pair.loop_lists.film_j.data(), nullptr, nfilm,
               [this](auto &&...a) { film_shear_pairs(a...); });
      run_list(pair.loop_lists.candidate_i.data(), pair.loop_lists.candidate_j.data(),
               pair.loop_lists.candidate_jj.data(), ncandidate, [this](auto &&...a) { friction_pairs(a...); });
      run_friction_events();
      return;
    }
    run_list(pair.loop_lists.film_i.data(), pair.loop_lists.film_j.data(), nullptr, nfilm,
             [this](auto &&...a) { film_pairs(a...); });
    run_list(pair.loop_lists.candidate_i.data(), pair.loop_lists.candidate_j.data(), nullptr, ncandidate,
             [this](auto &&...a) { kept_pairs(a...); });
    run_exits();
    run_events();
  }

 private:
  PairLubricatedSpringDashpot &pair;
  Evaluate &evaluate;
  const vector_pairs::Atoms atoms;
  // The per-atom arrays as the blocks they are (3 per atom): no row pointer to load per access.
  const double *x_all = pair.atom->x[0], *radius = pair.atom->radius;
  double *f_all = pair.atom->f[0], *torque_all = TANGENTIAL ? pair.atom->torque[0] : nullptr;
  const int *type = pair.atom->type;
  const int nlocal = pair.atom->nlocal, newton_pair = pair.force->newton_pair;
  const double dt = pair.update->dt;
  const bool records = pair.budget.active();    // the loops' films enter the film budget
  // The history through its flat arrays (each pair's entry), whose pointers then stay in
  // registers (a char store may alias what values(i) and touched(i) read).
  double *const history_values = pair.history ? pair.history->values_all() : nullptr;
  char *const history_touched = pair.history ? pair.history->touched_all() : nullptr;

  // A chunk's outputs: the whole force on i of chunk place c, the opposite on j; the films,
  // their capacities and the springs' energies; the shear films, torques and elongations.
  double force[3][chunk], energy[chunk], film[chunk], capacity[chunk], done[chunk];
  double shear[6][chunk], slip_sq[chunk], tangential_mass[chunk];
  double touched[chunk], delta[3][chunk], next[3][chunk], next_touched[chunk], torque_unit[3][chunk], on[chunk];
  const vector_pairs::ForceOut force_out{force[0], force[1], force[2]};
  const vector_pairs::ShearOut shear_out{force[0], force[1], force[2], shear[0], shear[1],       shear[2],
                                         shear[3], shear[4], shear[5], slip_sq,  tangential_mass};
  const vector_pairs::FrictionOut friction_out{
      film,           capacity,       energy,   force[0],     force[1], force[2], torque_unit[0],
      torque_unit[1], torque_unit[2], shear[0], shear[1],     shear[2], slip_sq,  tangential_mass,
      next[0],        next[1],        next[2],  next_touched, on};
  // Places in the chunk: pairs a loop left, pairs leaving the overlap, pairs for the general
  // loop; each pair's history entry (friction).
  int rest[chunk], leaving[chunk], left[chunk], entry[chunk];
  // Grouping a chunk by type pair.
  int key[chunk], grouped_i[chunk], grouped_j[chunk], grouped_jj[chunk];

  // Pairs a chunk leaves to a loop over few of them (contacts that start or end, exits),
  // gathered over chunks so that those loops run on whole vectors, not a few lanes and their
  // scalar remainder: run when full, before pairs of another model join, and at the end.
  struct Deferred {
    const ContactModel *model = nullptr;
    int n = 0;
    int i[chunk], j[chunk], jj[chunk], entry[chunk];    // entry: the history's (friction)
    double touched[chunk], delta[3][chunk];
    // Whether the list must run before it takes count pairs of this model.
    bool full_for(const ContactModel &other, int count) const { return model != &other || n + count > chunk; }
  };
  Deferred events, exits;

  void apply(int i, int j, int c, double eij)
  {
    const double fx = force[0][c], fy = force[1][c], fz = force[2][c];
    double *fi = f_all + 3 * i, *fj = f_all + 3 * j;
    fi[0] += fx, fi[1] += fy, fi[2] += fz;
    if (newton_pair || j < nlocal) fj[0] -= fx, fj[1] -= fy, fj[2] -= fz;
    if (pair.evflag) {
      const double *xi = x_all + 3 * i, *xj = x_all + 3 * j;
      pair.ev_tally_xyz(i, j, nlocal, newton_pair, eij, 0.0, fx, fy, fz, xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]);
    }
  }

  // A pair's force (fx, fy, fz) on i, the opposite on j; the torque (ux, uy, uz) per unit
  // radius on both; tallied (with energy eij) unless tallied = 0.
  __attribute__((always_inline)) void apply_tangential(int i, int j, double fx, double fy, double fz, double ux,
                                                       double uy, double uz, double eij, double tallied)
  {
    double *fi = f_all + 3 * i, *ti = torque_all + 3 * i;
    const double radi = radius[i];
    fi[0] += fx, fi[1] += fy, fi[2] += fz;
    ti[0] += radi * ux, ti[1] += radi * uy, ti[2] += radi * uz;
    if (newton_pair || j < nlocal) {
      double *fj = f_all + 3 * j, *tj = torque_all + 3 * j;
      const double radj = radius[j];
      fj[0] -= fx, fj[1] -= fy, fj[2] -= fz;
      tj[0] += radj * ux, tj[1] += radj * uy, tj[2] += radj * uz;
    }
    if (pair.evflag && tallied != 0.0) {
      const double *xi = x_all + 3 * i, *xj = x_all + 3 * j;
      pair.ev_tally_xyz(i, j, nlocal, newton_pair, eij, 0.0, fx, fy, fz, xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]);
    }
  }

  // The budget's records of a chunk's normal films (their kick is a step: the loops run in
  // steps only): the shares in a loop of their own (vectorised), the rest with the scatter.
  void record_normal_films(const int *pair_i, const int *pair_j, int n)
  {
    for (int c = 0; c < n; c++)
      capacity[c] = lubricated::film_share_of_capacity(film[c], capacity[c], dt);
    for (int c = 0; c < n; c++)
      pair.budget.record_film(pair_i[c], pair_j[c], film[c], capacity[c], nlocal, newton_pair);
  }

  // The same, and where the budget records shear films those too (shear, slip_sq,
  // tangential_mass); the contact's share the larger of the two.
  void record_normal_and_shear_films(const int *pair_i, const int *pair_j, int n)
  {
    for (int c = 0; c < n; c++) {
      const double share = lubricated::film_share_of_capacity(film[c], capacity[c], dt);
      if (!pair.budget.records_shear()) {
        pair.budget.record_film(pair_i[c], pair_j[c], film[c], share, nlocal, newton_pair);
        continue;
      }
      const lubricated::Vec3 shear_force{shear[0][c], shear[1][c], shear[2][c]};
      const double shear_share =
          lubricated::shear_film_share(lubricated::dot(shear_force, shear_force), slip_sq[c], tangential_mass[c], dt);
      pair.budget.record_films(pair_i[c], pair_j[c], film[c], shear_force,
                               lubricated::contact_film_share(share, shear_share), nlocal, newton_pair);
    }
  }

  // Film-only pairs: at most one chunk of one model.
  void film_pairs(const ContactModel &contact_model, const int *pair_i, const int *pair_j, const int * /*pair_jj*/,
                  int n)
  {
    const lubricated::NormalModel &model = contact_model.normal;
    if (atoms.inverse_mass)
      vector_pairs::film_only_by_inverse(atoms, model, pair_i, pair_j, n, force_out, film, capacity);
    else
      vector_pairs::film_only(atoms, model, pair_i, pair_j, n, force_out, film, capacity);
    for (int c = 0; c < n; c++)
      apply(pair_i[c], pair_j[c], c, 0.0);
    if (records) record_normal_films(pair_i, pair_j, n);
  }

  // The same with the shear film (friction or rolling: a shear film may act apart).
  void film_shear_pairs(const ContactModel &model, const int *pair_i, const int *pair_j, const int * /*pair_jj*/, int n)
  {
    if (atoms.inverse_mass)
      vector_pairs::film_shear_only_by_inverse(atoms, model, pair_i, pair_j, n, film, capacity, shear_out, records);
    else
      vector_pairs::film_shear_only(atoms, model, pair_i, pair_j, n, film, capacity, shear_out, records);
    for (int c = 0; c < n; c++)
      apply_tangential(pair_i[c], pair_j[c], force[0][c], force[1][c], force[2][c], shear[3][c], shear[4][c],
                       shear[5][c], 0.0, pair.evflag);
    if (records) record_normal_and_shear_films(pair_i, pair_j, n);
  }

  // The frictional loops' forces, torques and elongations scattered, the films' budget records
  // (the pairs not done have no film: no record); returns how many are not done, listed in out.
  __attribute__((always_inline)) int scatter_friction(const ContactModel &model, const int *list_i, const int *list_j,
                                                      const int *list_entry, int count, int *out)
  {
    int nrest = 0;
    for (int c = 0; c < count; c++) {
      // Branch-free: the pairs not done have zero forces and their history unchanged here.
      apply_tangential(list_i[c], list_j[c], force[0][c], force[1][c], force[2][c], torque_unit[0][c],
                       torque_unit[1][c], torque_unit[2][c], energy[c], on[c]);
      const int e = list_entry[c];
      double *h = history_values + 3 * e;
      h[0] = next[0][c], h[1] = next[1][c], h[2] = next[2][c];
      history_touched[e] = static_cast<char>(next_touched[c]);
      out[nrest] = c;
      nrest += on[c] == 0.0;
    }
    if (records && model.normal.lubrication.active()) record_normal_and_shear_films(list_i, list_j, count);
    return nrest;
  }

  // Frictional contacts that start or end, and new ones (no entry loss): their own loop, the
  // pairs it leaves through the general loop.
  void run_friction_events()
  {
    if (events.n == 0) return;
    const ContactModel &model = *events.model;
    const vector_pairs::FrictionIn in{events.i,        events.j,        events.touched,
                                      events.delta[0], events.delta[1], events.delta[2]};
    if (atoms.inverse_mass)
      vector_pairs::friction_events_by_inverse(atoms, model, in, events.n, friction_out);
    else
      vector_pairs::friction_events(atoms, model, in, events.n, friction_out);
    const int nleft = scatter_friction(model, events.i, events.j, events.entry, events.n, left);
    for (int k = 0; k < nleft; k++)
      evaluate(events.i[left[k]], events.j[left[k]], events.jj[left[k]]);
    events.n = 0;
  }

  // The chunk's elongations and touched flags from the history. Its entries fetched ahead (a few
  // of the history's cache lines each, in a large bed beyond the L2 cache), then read; the flag (0
  // or 1) converted, not tested: a branch on it waits for its load.
  void gather_history(const int *pair_i, const int *pair_jj, int n)
  {
    for (int c = 0; c < n; c++) {
      const int e = pair.history->entry(pair_i[c], pair_jj[c]);
      entry[c] = e;
      __builtin_prefetch(history_values + 3 * e);
      __builtin_prefetch(history_touched + e);
    }
    for (int c = 0; c < n; c++) {
      const int e = entry[c];
      const double *h = history_values + 3 * e;
      delta[0][c] = h[0], delta[1][c] = h[1], delta[2][c] = h[2];
      touched[c] = history_touched[e];
    }
  }

  // Sustained frictional contacts (TANGENTIAL): the elongations gathered, the whole contact
  // vectorised, forces, torques and elongations scattered; the rest through the event loop or
  // the general loop.
  void friction_pairs(const ContactModel &model, const int *pair_i, const int *pair_j, const int *pair_jj, int n)
  {
    const lubricated::TangentialModel &tm = model.tangential;
    if (!pair.history || !tm.contact_active() || tm.rolling_active()) {
      for (int c = 0; c < n; c++)
        evaluate(pair_i[c], pair_j[c], pair_jj[c]);
      return;
    }
    gather_history(pair_i, pair_jj, n);
    const vector_pairs::FrictionIn in{pair_i, pair_j, touched, delta[0], delta[1], delta[2]};
    if (atoms.inverse_mass)
      vector_pairs::friction_contacts_by_inverse(atoms, model, in, n, friction_out);
    else
      vector_pairs::friction_contacts(atoms, model, in, n, friction_out);
    const int nrest = scatter_friction(model, pair_i, pair_j, entry, n, rest);
    if (model.normal.calibrated()) {
      for (int k = 0; k < nrest; k++)
        evaluate(pair_i[rest[k]], pair_j[rest[k]], pair_jj[rest[k]]);
      return;
    }
    if (events.full_for(model, nrest)) run_friction_events();
    events.model = &model;
    for (int k = 0; k < nrest; k++) {
      const int c = rest[k], e = events.n + k;
      events.i[e] = pair_i[c], events.j[e] = pair_j[c], events.jj[e] = pair_jj[c], events.entry[e] = entry[c];
      events.touched[e] = touched[c];
      events.delta[0][e] = delta[0][c], events.delta[1][e] = delta[1][c], events.delta[2][e] = delta[2][c];
    }
    events.n += nrest;
  }

  // Contacts that leave the overlap within the step: their own loop.
  void run_exits()
  {
    if (exits.n == 0) return;
    const lubricated::NormalModel &model = exits.model->normal;
    if (atoms.inverse_mass)
      vector_pairs::contact_exits_by_inverse(atoms, model, exits.i, exits.j, exits.n, force_out, film, capacity,
                                             energy);
    else
      vector_pairs::contact_exits(atoms, model, exits.i, exits.j, exits.n, force_out, film, capacity, energy);
    for (int c = 0; c < exits.n; c++)
      apply(exits.i[c], exits.j[c], c, energy[c]);
    if (records && model.lubrication.active()) record_normal_films(exits.i, exits.j, exits.n);
    exits.n = 0;
  }

  // Contacts that start or end (no entry loss): their own loop, the pairs it leaves (whose root
  // needs more than one Newton step) through the general loop.
  void run_events()
  {
    if (events.n == 0) return;
    const lubricated::NormalModel &model = events.model->normal;
    if (atoms.inverse_mass)
      vector_pairs::contact_events_by_inverse(atoms, model, events.i, events.j, events.n, force_out, film, capacity,
                                              energy, done);
    else
      vector_pairs::contact_events(atoms, model, events.i, events.j, events.n, force_out, film, capacity, energy, done);
    int nleft = 0;
    for (int c = 0; c < events.n; c++) {
      apply(events.i[c], events.j[c], c, energy[c]);
      left[nleft] = c;
      nleft += done[c] == 0.0;
    }
    if (records && model.lubrication.active()) record_normal_films(events.i, events.j, events.n);
    for (int k = 0; k < nleft; k++)
      evaluate(events.i[left[k]], events.j[left[k]], 0);
    events.n = 0;
  }

  // Kept pairs without tangential parts: sustained contacts and pairs apart over the step in
  // one loop; those leaving the overlap and those where a contact starts or ends deferred.
  void kept_pairs(const ContactModel &contact_model, const int *pair_i, const int *pair_j, const int * /*pair_jj*/,
                  int n)
  {
    const lubricated::NormalModel &model = contact_model.normal;
    if (atoms.inverse_mass)
      vector_pairs::contact_or_film_by_inverse(atoms, model, pair_i, pair_j, n, force_out, film, capacity, energy,
                                               done);
    else
      vector_pairs::contact_or_film(atoms, model, pair_i, pair_j, n, force_out, film, capacity, energy, done);
    int nrest = 0, nexit = 0;
    for (int c = 0; c < n; c++) {
      // Branch-free (which pairs are done follows no pattern): the others have no force (and
      // no film) here and are listed, those leaving the overlap for their own loop, the rest
      // (contacts that start or end) for theirs, or the general loop with an entry loss.
      apply(pair_i[c], pair_j[c], c, energy[c]);
      leaving[nexit] = c;
      nexit += done[c] == 2.0;
      rest[nrest] = c;
      nrest += done[c] == 0.0;
    }
    if (records && model.lubrication.active()) record_normal_films(pair_i, pair_j, n);
    if (exits.full_for(contact_model, nexit)) run_exits();
    exits.model = &contact_model;
    for (int k = 0; k < nexit; k++)
      exits.i[exits.n + k] = pair_i[leaving[k]], exits.j[exits.n + k] = pair_j[leaving[k]];
    exits.n += nexit;
    if (model.calibrated()) {
      for (int k = 0; k < nrest; k++)
        evaluate(pair_i[rest[k]], pair_j[rest[k]], 0);
      return;
    }
    if (events.full_for(contact_model, nrest)) run_events();
    events.model = &contact_model;
    for (int k = 0; k < nrest; k++)
      events.i[events.n + k] = pair_i[rest[k]], events.j[events.n + k] = pair_j[rest[k]];
    events.n += nrest;
  }

  // A list in chunks, each grouped by type pair (a counting sort within the chunk, which keeps
  // the atoms' data in the cache) unless one model serves all. list_jj (the history's list
  // entries, with friction) is grouped with the pairs where given.
  template <class Pairs> void run_list(const int *list_i, const int *list_j, const int *list_jj, int count, Pairs pairs)
  {
    std::vector<int> &group_count = pair.loop_lists.group_count;
    group_count.resize(pair.models.size(), 0);    // all zero between chunks
    for (int start = 0; start < count; start += chunk) {
      const int n = std::min(chunk, count - start);
      const int *pair_i = list_i + start, *pair_j = list_j + start;
      const int *pair_jj = list_jj ? list_jj + start : nullptr;
      if (pair.uniform_models) {
        pairs(pair.models[pair.index(1, 1)], pair_i, pair_j, pair_jj, n);
        continue;
      }
      group_by_type_pair(pair_i, pair_j, pair_jj, n);
      int begin = 0;
      for (int k : pair.loop_lists.group_keys) {
        pairs(pair.models[k], grouped_i + begin, grouped_j + begin, grouped_jj + begin, group_count[k] - begin);
        begin = group_count[k];
        group_count[k] = 0;
      }
    }
  }

  // The chunk's pairs into grouped_i/j/jj, type pair after type pair (group_keys, in the order
  // met); group_count[k] is left at the end of group k.
  void group_by_type_pair(const int *pair_i, const int *pair_j, const int *pair_jj, int n)
  {
    std::vector<int> &group_count = pair.loop_lists.group_count, &group_keys = pair.loop_lists.group_keys;
    group_keys.clear();
    for (int c = 0; c < n; c++) {
      key[c] = pair.index(type[pair_i[c]], type[pair_j[c]]);
      if (group_count[key[c]]++ == 0) group_keys.push_back(key[c]);
    }
    int begin = 0;
    for (int k : group_keys) {    // group_count becomes each group's next free slot
      const int size = group_count[k];
      group_count[k] = begin;
      begin += size;
    }
    for (int c = 0; c < n; c++) {
      const int at = group_count[key[c]]++;
      grouped_i[at] = pair_i[c];
      grouped_j[at] = pair_j[c];
      if (pair_jj) grouped_jj[at] = pair_jj[c];
    }
  }
};

template <bool TANGENTIAL, class Evaluate> void
PairLubricatedSpringDashpot::vector_forces(int ncandidate, int nfilm, double **v, double **omega, Evaluate &evaluate)
{
  if (ncandidate + nfilm == 0) return;
  VectorForces<TANGENTIAL, Evaluate>(*this, v, omega, evaluate).run(ncandidate, nfilm);
}

}    // namespace LAMMPS_NS

#endif
