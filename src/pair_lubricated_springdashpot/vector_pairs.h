/* -*- c++ -*- ----------------------------------------------------------
   Vectorised loops of pair style lubricated/springdashpot for the two common kinds of pair:
   pairs that stay apart over the coming step (the film alone, lubricated::film_force_apart)
   and pairs in sustained contact (lubricated::sustained_contact_force). Loops without branches that
   the compiler vectorises (gathers of the atoms' data), for the instruction set found when
   the plugin is loaded. The pair style applies the forces and takes every other pair through
   its general loop.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_VECTOR_PAIRS_H
#define LMP_LUBRICATED_VECTOR_PAIRS_H

#include "lubricated/contact.h"
#include "lubricated/film_budget.h"
#include "lubricated/normal_model.h"
#include "lubricated/pair_geometry.h"

namespace LAMMPS_NS {
namespace vector_pairs {

// Per-atom data (lubricated/pair_geometry.h): x, v, radius, rmass, inverse_mass (nullptr: m_e
// from rmass), omega (the slip: friction and shear film loops only).
using Atoms = lubricated::PairAtoms;

// The pairs (pair_i[c], pair_j[c]), c < n, all of model `model` (exact integration, a step).
// force: the whole force on i (force.x[c], force.y[c], force.z[c]), on j the opposite; film[c]
// the film part of the force (along n, its size) and capacity[c] = m_e |u_n|, from which the
// caller takes the pair's share of the many-body film budget (lubricated/film_budget.h).
struct ForceOut {
  double *x, *y, *z;
};

// Pairs apart by more than both atoms move in the step, with an active film.
void film_only(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i, const int *pair_j, int n,
               const ForceOut &force, double *film, double *capacity);

// Pairs that may touch within the step (done as doubles): done[c] = 1 where pair c is in
// sustained contact or stays apart over the step (the film alone), with its force and spring
// energy[c]; 2 where it leaves the overlap within the step (for contact_exits), 0 where a
// contact starts or ends otherwise, for the general loop (force, energy 0 for both).
void contact_or_film(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i, const int *pair_j,
                     int n, const ForceOut &force, double *film, double *capacity, double *energy, double *done);

// Pairs that contact_or_film marked 2 (leaving the overlap within the step): its outputs.
void contact_exits(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i, const int *pair_j,
                   int n, const ForceOut &force, double *film, double *capacity, double *energy);

// Pairs that contact_or_film marked 0 (a contact starts within the step, or started or ended
// within the last one) of a model without an entry loss (!model.calibrated()): done[c] = 1 with
// its outputs where lubricated::contact_event_force resolves pair c, else 0 (for the general
// loop; outputs 0).
void contact_events(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i, const int *pair_j,
                    int n, const ForceOut &force, double *film, double *capacity, double *energy, double *done);
void contact_events_by_inverse(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i,
                               const int *pair_j, int n, const ForceOut &force, double *film, double *capacity,
                               double *energy, double *done);

// The same with m_e from atoms.inverse_mass (a pair of two immovable atoms: all 0, done).
void contact_exits_by_inverse(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i,
                              const int *pair_j, int n, const ForceOut &force, double *film, double *capacity,
                              double *energy);
void film_only_by_inverse(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i,
                          const int *pair_j, int n, const ForceOut &force, double *film, double *capacity);
void contact_or_film_by_inverse(const Atoms &atoms, const lubricated::NormalModel &model, const int *pair_i,
                                const int *pair_j, int n, const ForceOut &force, double *film, double *capacity,
                                double *energy, double *done);

// Pairs apart by more than both atoms move in the step, with friction or rolling (which act in
// contact only) and maybe a shear film: film_only's outputs, the whole force on i (force_x/y/z:
// the film along n and the shear film; on j the opposite), the shear film's force on i alone
// (shear_x/y/z, 0 without a shear film), the torque it makes per unit radius (torque_x/y/z: on
// i times R_i, on j times R_j), the slip's squared length and the tangential mass, from which
// the caller takes the shear film's budget share. records: whether film, capacity, shear_x/y/z,
// slip_sq and tangential_mass (the budget's inputs) are written; the force and torque always.
struct ShearOut {
  double *force_x, *force_y, *force_z, *shear_x, *shear_y, *shear_z, *torque_x, *torque_y, *torque_z, *slip_sq,
      *tangential_mass;
};
void film_shear_only(const Atoms &atoms, const lubricated::ContactModel &model, const int *pair_i, const int *pair_j,
                     int n, double *film, double *capacity, const ShearOut &shear, bool records = true);
void film_shear_only_by_inverse(const Atoms &atoms, const lubricated::ContactModel &model, const int *pair_i,
                                const int *pair_j, int n, double *film, double *capacity, const ShearOut &shear,
                                bool records = true);

// Kept pairs with friction (no rolling resistance) and maybe a film and a shear film: done[c] =
// 1.0 where pair c is in overlap now, a step ago and a step ahead (as contact_or_film decides)
// and touched at the last step (touched[c] != 0), or apart over the step (the films alone), with
// the whole contact of lubricated::contact_forces<true> for it: film, capacity, energy as above;
// force_x/y/z the whole force on i (normal along n, friction and shear film; on j the opposite),
// torque_x/y/z the torque per unit radius (on i times R_i, on j times R_j), shear_x/y/z the shear
// film alone, slip_sq and tangential_mass for its budget share, new_x/y/z and new_touched the
// elongation and touched flag after the step (delta_x/y/z and touched before it). done[c] = 0.0:
// for the general loop (no force; new = delta, new_touched = touched, tangential_mass = 1).
struct FrictionIn {
  const int *pair_i, *pair_j;
  const double *touched, *delta_x, *delta_y, *delta_z;
};
struct FrictionOut {
  double *film, *capacity, *energy, *force_x, *force_y, *force_z, *torque_x, *torque_y, *torque_z;
  double *shear_x, *shear_y, *shear_z, *slip_sq, *tangential_mass, *new_x, *new_y, *new_z, *new_touched;
  double *done;    // 1 or 0 (an int output stops GCC 12 vectorising the loop with inverse masses)
};
void friction_contacts(const Atoms &atoms, const lubricated::ContactModel &model, const FrictionIn &in, int n,
                       const FrictionOut &out);
void friction_contacts_by_inverse(const Atoms &atoms, const lubricated::ContactModel &model, const FrictionIn &in,
                                  int n, const FrictionOut &out);

// The kept pairs friction_contacts leaves (done 0: a contact that starts or ends, or one new since
// the last step) of a model without an entry loss (!model.normal.calibrated()): the same outputs,
// the normal force by lubricated::contact_event_force, the spring where in overlap (from the part
// of the last step in overlap where the contact is new), the elongation forgotten elsewhere;
// done[c] = 1 where that resolves pair c, else 0 (for the general loop).
void friction_events(const Atoms &atoms, const lubricated::ContactModel &model, const FrictionIn &in, int n,
                     const FrictionOut &out);
void friction_events_by_inverse(const Atoms &atoms, const lubricated::ContactModel &model, const FrictionIn &in, int n,
                                const FrictionOut &out);

}    // namespace vector_pairs
}    // namespace LAMMPS_NS

#endif
