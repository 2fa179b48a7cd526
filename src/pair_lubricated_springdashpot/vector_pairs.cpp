/* ----------------------------------------------------------------------
   Vectorised loops of pair style lubricated/springdashpot (see vector_pairs.h)
------------------------------------------------------------------------- */

#include "vector_pairs.h"

#include "lubricated/film_only_loop.h"
#include "lubricated/vector_clones.h"
#include "vector_friction_loops.h"

#include <cmath>

namespace lub = lubricated;

namespace LAMMPS_NS {
namespace vector_pairs {

using lub::pair_geometry;
using Geometry = lub::PairGeometry;

template <bool WET, bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
contact_or_film_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
                     const int *__restrict pair_j, int n, double *__restrict force_x, double *__restrict force_y,
                     double *__restrict force_z, double *__restrict film_force, double *__restrict capacity,
                     double *__restrict energy, double *__restrict done)
{
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  for (int c = 0; c < n; c++) {
    const Geometry g = pair_geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const double gap = g.r - g.radsum;
    // Apart over the step (no contact can act): the film alone, as in film_only. Wet, its
    // lambda(eps_al) serves the sustained contact's saturated film too (one logarithm fewer).
    double shear_log, lambda_al = 0.0;
    const double film = WET ? lub::film_force_apart<GRID>(model.lubrication, gap, g.film, g.m_e, g.u_n, dt, inv_dt,
                                                          shear_log, lambda_al)
                            : 0.0;
    bool sustained;
    const lub::NormalForce contact =
        WET ? lub::sustained_contact_force(model, gap, g.film, g.m_e, g.u_n, lambda_al, sustained)
            : lub::sustained_contact_force<GRID>(model, gap, g.film, g.m_e, g.u_n, sustained);
    const bool apart = !lub::contact_possible(gap, g.u_n, dt);
    const bool known = (sustained | apart) & (g.r > 0.0);
    const double fpair = known ? (sustained ? contact.total() : film) * g.rinv : 0.0;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    // The shares themselves are divided out by the caller: with that division in it, GCC 12
    // no longer if-converts (and vectorises) this loop.
    film_force[c] = WET & known ? (sustained ? contact.lubrication : film) : 0.0;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = known & sustained ? contact.energy : 0.0;
    // 2: leaving the overlap within the coming step (contact_exits; never known: in overlap,
    // not sustained). Doubles: with an int output GCC 12 does not vectorise this loop.
    const bool exits = lub::leaves_overlap(model.step, gap, gap - g.u_n * dt) & (g.r > 0.0);
    done[c] = (known ? 1.0 : 0.0) + (exits ? 2.0 : 0.0);
  }
}

// Kept pairs that leave the overlap within the coming step (lub::leaves_overlap): the exit's
// force, the saturated film and the spring's energy; as contact_or_film's outputs.
template <bool WET, bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
contact_exit_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
                  const int *__restrict pair_j, int n, double *__restrict force_x, double *__restrict force_y,
                  double *__restrict force_z, double *__restrict film_force, double *__restrict capacity,
                  double *__restrict energy)
{
  for (int c = 0; c < n; c++) {
    const Geometry g = pair_geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const lub::NormalForce f = lub::overlap_exit_force<GRID>(model, g.r - g.radsum, g.film, g.m_e, g.u_n);
    const double fpair = f.total() * g.rinv;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    film_force[c] = WET ? f.lubrication : 0.0;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = f.energy;
  }
}

// Kept pairs where a contact starts or ends (contact_or_film's done = 0) of a model without an
// entry loss: done[c] = 1 with contact_or_film's outputs where lub::contact_event_force resolves
// pair c (or neither atom moves: no force), else 0 for the general loop (outputs 0).
template <bool WET, bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
contact_event_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
                   const int *__restrict pair_j, int n, double *__restrict force_x, double *__restrict force_y,
                   double *__restrict force_z, double *__restrict film_force, double *__restrict capacity,
                   double *__restrict energy, double *__restrict done)
{
  // Local copies (as film_shear_only_loop): no store can alias them, so their loads (the guess
  // tables' pointers among them) leave the loop.
  const Atoms local = atoms;
  const lub::NormalModel local_model = model;
  for (int c = 0; c < n; c++) {
    const Geometry g = pair_geometry<INVERSE>(local, pair_i[c], pair_j[c]);
    bool resolved;
    const lub::NormalForce f =
        lub::contact_event_force<WET, GRID>(local_model, g.r - g.radsum, g.film, g.m_e, g.u_n, resolved);
    // Whether the pair moves as a double (a bool of m_e > 0 stops GCC 12 vectorising the loop
    // with inverse masses); a pair neither of whose atoms moves is done without a force.
    const double moving = g.m_e > 0.0 ? 1.0 : 0.0;
    const bool known = resolved & (moving != 0.0) & (g.r > 0.0);
    const double fpair = known ? f.total() * g.rinv : 0.0;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    film_force[c] = WET & known ? f.lubrication : 0.0;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = known ? f.energy : 0.0;
    done[c] = g.r > 0.0 ? (resolved ? 1.0 : 1.0 - moving) : 0.0;
  }
}

// Each entry point compiles its own loops (the plain ones exactly as without contact masses).
LUBRICATED_VECTOR_CLONES
void film_only(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
               const ForceOut &force, double *film, double *capacity)
{
  if (model.lubrication.grid_spacing > 0.0)
    lub::film_only_loop<true, false, false>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
                                            nullptr);
  else
    lub::film_only_loop<false, false, false>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
                                             nullptr);
}

LUBRICATED_VECTOR_CLONES
void film_only_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                          int n, const ForceOut &force, double *film, double *capacity)
{
  if (model.lubrication.grid_spacing > 0.0)
    lub::film_only_loop<true, true, false>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
                                           nullptr);
  else
    lub::film_only_loop<false, true, false>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
                                            nullptr);
}

// The loop LOOP<WET, GRID, INVERSE> for the model's film: dry, wet with a grid, wet without.
#define NORMAL_LOOP(LOOP, INVERSE, ...)                                                                                \
  do {                                                                                                                 \
    const bool wet = model.lubrication.active(), grid = model.lubrication.grid_spacing > 0.0;                          \
    if (!wet)                                                                                                          \
      LOOP<false, false, INVERSE>(__VA_ARGS__);                                                                        \
    else if (grid)                                                                                                     \
      LOOP<true, true, INVERSE>(__VA_ARGS__);                                                                          \
    else                                                                                                               \
      LOOP<true, false, INVERSE>(__VA_ARGS__);                                                                         \
  } while (false)

LUBRICATED_VECTOR_CLONES
void contact_or_film(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
                     const ForceOut &force, double *film, double *capacity, double *energy, double *done)
{
  NORMAL_LOOP(contact_or_film_loop, false, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

LUBRICATED_VECTOR_CLONES
void contact_or_film_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                                int n, const ForceOut &force, double *film, double *capacity, double *energy,
                                double *done)
{
  NORMAL_LOOP(contact_or_film_loop, true, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

LUBRICATED_VECTOR_CLONES
void contact_exits(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
                   const ForceOut &force, double *film, double *capacity, double *energy)
{
  NORMAL_LOOP(contact_exit_loop, false, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy);
}

LUBRICATED_VECTOR_CLONES
void contact_exits_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                              int n, const ForceOut &force, double *film, double *capacity, double *energy)
{
  NORMAL_LOOP(contact_exit_loop, true, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy);
}

LUBRICATED_VECTOR_CLONES
void contact_events(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
                    const ForceOut &force, double *film, double *capacity, double *energy, double *done)
{
  NORMAL_LOOP(contact_event_loop, false, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

LUBRICATED_VECTOR_CLONES
void contact_events_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                               int n, const ForceOut &force, double *film, double *capacity, double *energy,
                               double *done)
{
  NORMAL_LOOP(contact_event_loop, true, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

#undef NORMAL_LOOP

#define SHEAR_OUTPUTS(o)                                                                                               \
  o.force_x, o.force_y, o.force_z, o.shear_x, o.shear_y, o.shear_z, o.torque_x, o.torque_y, o.torque_z, o.slip_sq,     \
      o.tangential_mass

// film_shear_only_loop<GRID, INVERSE, RECORDS> for the model's film and the caller's records.
#define SHEAR_LOOP(INVERSE)                                                                                            \
  do {                                                                                                                 \
    const bool grid = model.normal.lubrication.grid_spacing > 0.0;                                                     \
    if (grid && records)                                                                                               \
      film_shear_only_loop<true, INVERSE, true>(atoms, model, pair_i, pair_j, n, film, capacity,                       \
                                                SHEAR_OUTPUTS(shear));                                                 \
    else if (grid)                                                                                                     \
      film_shear_only_loop<true, INVERSE, false>(atoms, model, pair_i, pair_j, n, film, capacity,                      \
                                                 SHEAR_OUTPUTS(shear));                                                \
    else if (records)                                                                                                  \
      film_shear_only_loop<false, INVERSE, true>(atoms, model, pair_i, pair_j, n, film, capacity,                      \
                                                 SHEAR_OUTPUTS(shear));                                                \
    else                                                                                                               \
      film_shear_only_loop<false, INVERSE, false>(atoms, model, pair_i, pair_j, n, film, capacity,                     \
                                                  SHEAR_OUTPUTS(shear));                                               \
  } while (false)

LUBRICATED_VECTOR_CLONES
void film_shear_only(const Atoms &atoms, const lub::ContactModel &model, const int *pair_i, const int *pair_j, int n,
                     double *film, double *capacity, const ShearOut &shear, bool records)
{
  SHEAR_LOOP(false);
}

LUBRICATED_VECTOR_CLONES
void film_shear_only_by_inverse(const Atoms &atoms, const lub::ContactModel &model, const int *pair_i,
                                const int *pair_j, int n, double *film, double *capacity, const ShearOut &shear,
                                bool records)
{
  SHEAR_LOOP(true);
}

#undef SHEAR_LOOP

#define CONTACT_ARGUMENTS(o)                                                                                           \
  o.film, o.capacity, o.energy, o.force_x, o.force_y, o.force_z, o.torque_x, o.torque_y, o.torque_z, o.shear_x,        \
      o.shear_y, o.shear_z, o.slip_sq, o.tangential_mass, o.new_x, o.new_y, o.new_z, o.new_touched, o.done

// One entry point per mass form; the model picks the loop (dry; wet with or without a grid and a
// shear film).
template <bool INVERSE, bool EVENTS> __attribute__((always_inline)) static inline void
friction_contacts_of(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                     const FrictionOut &out)
{
  const lub::Lubrication &film = model.normal.lubrication;
  const bool wet = film.active(), grid = film.grid_spacing > 0.0, shear = model.tangential.film_active();
#define FRICTION_LOOP(W, G, S)                                                                                         \
  friction_contact_loop<W, G, S, INVERSE, EVENTS>(atoms, model, in.pair_i, in.pair_j, in.touched, in.delta_x,          \
                                                  in.delta_y, in.delta_z, n, CONTACT_ARGUMENTS(out))
  if (!wet)
    FRICTION_LOOP(false, false, false);
  else if (grid && shear)
    FRICTION_LOOP(true, true, true);
  else if (grid)
    FRICTION_LOOP(true, true, false);
  else if (shear)
    FRICTION_LOOP(true, false, true);
  else
    FRICTION_LOOP(true, false, false);
#undef FRICTION_LOOP
}

LUBRICATED_VECTOR_CLONES
void friction_contacts(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                       const FrictionOut &out)
{
  friction_contacts_of<false, false>(atoms, model, in, n, out);
}

LUBRICATED_VECTOR_CLONES
void friction_contacts_by_inverse(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                                  const FrictionOut &out)
{
  friction_contacts_of<true, false>(atoms, model, in, n, out);
}

LUBRICATED_VECTOR_CLONES
void friction_events(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                     const FrictionOut &out)
{
  friction_contacts_of<false, true>(atoms, model, in, n, out);
}

LUBRICATED_VECTOR_CLONES
void friction_events_by_inverse(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                                const FrictionOut &out)
{
  friction_contacts_of<true, true>(atoms, model, in, n, out);
}

}    // namespace vector_pairs
}    // namespace LAMMPS_NS
