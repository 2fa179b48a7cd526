/* -*- c++ -*- ----------------------------------------------------------
   A fix whose force on each atom is a linear damper toward the fluid, c (u_f - v) and
   c_r (Omega_f - omega) (fix fluid/drag's drag and torque), taken implicitly by the coupled film
   solve (doc/film_solve.rst, "Drag in the solve"): before the solve the fix gives c, c_r, u_f
   and Omega_f of the owned atoms at the velocities w of the evaluation; the solve puts c (u_f - w)
   into F and c into its matrix and hands back the increments x of the step; the fix then applies
   c (u_f - w - x) in place of its explicit c (u_f - w), so that the films, the contacts and the
   drag balance within the step. Where the fix solves the sphere's acceleration with the fluid's
   inertia (added mass, history), the solve moves that mass too.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_IMPLICIT_DRAG_H
#define LMP_LUBRICATED_IMPLICIT_DRAG_H

#include "lmptype.h"

namespace LAMMPS_NS {

class ImplicitDragParticipant {
 public:
  // Whether this step's drag can be solved with the films (linear in v, known before the pair
  // style evaluates); called on every rank at each solve, it may prepare the step's drag (a
  // collective solid fraction).
  virtual bool drag_is_implicit() = 0;
  // Owned atom i at velocity v and spin omega: drag coefficient c, the fluid velocity u_f,
  // rotational coefficient c_r and fluid rotation Omega_f (all 0 for an atom the fix does not act
  // on), and the inertia the fix solves for with the atom beyond its contact mass (the current
  // step's weight of a history force; an added mass is in the contact mass, contact_mass.h).
  struct LinearDrag {
    double drag = 0.0, rotational_drag = 0.0, solved_mass = 0.0;
    double fluid_velocity[3] = {0.0, 0.0, 0.0}, fluid_spin[3] = {0.0, 0.0, 0.0};
  };
  virtual LinearDrag linear_drag(int i, const double *v) = 0;
  // The solve's increments of this step: 6 per atom (velocity, spin), the owned atoms first.
  virtual void take_increments(const double *increments, int nlocal, bigint step) = 0;

 protected:
  ~ImplicitDragParticipant() = default;    // not deleted through this interface
};

}    // namespace LAMMPS_NS

#endif
