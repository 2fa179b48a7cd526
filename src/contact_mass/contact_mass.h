/* -*- c++ -*- ----------------------------------------------------------
   The mass a contact moves (doc/model.rst, "Solid contact: the spring-dashpot": m_e =
   (1/m_i + 1/m_j)^-1, m_i on a wall), for pair_style lubricated/springdashpot and fix wall/lubrication. An atom no contact can
   move counts with infinite mass: one left out of every time-integrating fix (when there is
   one), held by fix freeze or by `fix setforce 0 0 0`, or moved by fix move or nve/noforce.
   An atom of a rigid body (fix rigid, rigid/small and their variants) counts with the body's
   total mass, as the built-in granular pair styles do.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_CONTACT_MASS_H
#define LMP_LUBRICATED_CONTACT_MASS_H

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ContactMass : protected Pointers {
 public:
  explicit ContactMass(class LAMMPS *lmp) : Pointers(lmp) {}

  // At each run's init: finds the fixes that hold atoms or integrate rigid bodies and counts
  // the atoms concerned (a collective call); logs them for `who` when asked. active(): some
  // atom is immovable or in a rigid body; otherwise every atom moves with its rmass.
  void init(const std::string &who, bool log);
  bool active() const { return any; }

  // Inverse contact mass of owned atoms (0 immovable, 1 / M_body, 1 / rmass) into inverse[0,
  // nlocal). Reads the rigid fixes' body indices and masses as they are now.
  void fill(double *inverse);

  // Notes the arguments of every fix setforce created from now on in this LAMMPS instance
  // (a Fix keeps no copy of them, and only `setforce 0 0 0` without region holds): wraps the
  // built-in factory. Called at plugin load and, since `clear` restores the factories, by the
  // constructors of the plugin's styles.
  static void watch_setforce(class LAMMPS *lmp);

 private:
  int held_bits = 0;          // groups of fix freeze, setforce 0 0 0, move, nve/noforce
  int integrated_bits = 0;    // groups of the time-integrating fixes
  bool any_integrator = false;
  std::vector<class Fix *> rigid;
  bool any = false;
  bool held(int mask) const { return (mask & held_bits) || (any_integrator && !(mask & integrated_bits)); }
};

// The smallest radius of the atoms of a group over all ranks, at a run's set-up, after refusing
// a point particle (diameter 0: no contact surface and no film, R = 0 in 1/eps) with an ERROR
// naming the atom (style: the command's name for the message).
double smallest_sphere_radius(LAMMPS *lmp, const char *style, int groupbit);

}    // namespace LAMMPS_NS

#endif
