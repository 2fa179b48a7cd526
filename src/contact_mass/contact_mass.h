/* -*- c++ -*- ----------------------------------------------------------
   The mass a contact moves (doc/model.rst, "Solid contact: the spring-dashpot": m_e =
   (1/m_i + 1/m_j)^-1, m_i on a wall), for pair_style lubricated/springdashpot and fix wall/lubrication. An atom no contact can
   move counts with infinite mass: one left out of every time-integrating fix (when there is
   one), held by fix freeze or by `fix setforce 0 0 0`, or moved by fix move or nve/noforce.
   An atom of a rigid body (fix rigid, rigid/small and their variants) counts with the body's
   total mass, as the built-in granular pair styles do. A sphere of the group of a fix fluid/drag
   with added_mass carries the fluid's added mass into its contacts: m + C_m rho_f V, the mass
   that fix divides the total force by (doc/fix_fluid_drag.rst, "Added mass at contact").
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_CONTACT_MASS_H
#define LMP_LUBRICATED_CONTACT_MASS_H

#include "pointers.h"

#include "lubricated/wall_added_mass.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ContactMass : protected Pointers {
 public:
  explicit ContactMass(class LAMMPS *lmp) : Pointers(lmp) {}

  // At each run's init: finds the fixes that hold atoms, integrate rigid bodies or give spheres
  // an added mass and counts the atoms concerned (a collective call); logs them for `who` when
  // asked. active(): some atom is immovable, in a rigid body or carries an added mass; otherwise
  // every atom moves with its rmass. holds_or_rigid(): the first two, whose velocities a set-up
  // that continues the last run cannot reconstruct. carries_added_mass(): the third, whose
  // translation carries more than the sphere's own mass (m_t: tangential_mass_of_sides).
  void init(const std::string &who, bool log);
  bool active() const { return any; }
  bool holds_or_rigid() const { return any_held_or_rigid; }
  bool carries_added_mass() const { return !carried.empty(); }

  // Inverse contact mass of owned atoms (0 immovable, 1 / M_body, 1 / (rmass + m_a)) into
  // inverse[0, nlocal). Reads the rigid fixes' body indices and masses as they are now.
  void fill(double *inverse);

  // The fluid's added mass m_a = C_m rho_f V that owned atom i carries (0 outside the groups of
  // fix fluid/drag with added_mass).
  double added_mass(int i) const;

  // Where fix fluid/drag's keyword wall makes the added mass grow near plane walls, per axis
  // (lubricated/wall_added_mass.h): the contact mass of owned atom i along the unit normal n of a
  // wall contact, 1/m_e = sum_d n_d^2 / (m + m_a,d) with the masses that fix divides by at the
  // atom's position (in overlap: their values in contact); `mass` for an atom without added
  // mass, immovable or in a rigid body. near_walls(): whether any such fix is defined.
  bool near_walls() const { return any_near_walls; }
  double along_normal(int i, double nx, double ny, double nz, double mass) const;

  // The part of a force on owned atom i that fix fluid/drag leaves it, m / m_e with m_e the
  // contact mass it carries (along_normal): a steady load such as gravity accelerates it by
  // that fraction (1 for an atom without added mass, immovable or in a rigid body).
  double own_fraction(int i, double mass) const;

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
  struct Carried {    // a fix fluid/drag with added_mass: its group, C_m, rho_f and keyword wall
    int groupbit;
    double coefficient, density;
    const std::vector<lubricated::AddedMassWall> *walls;
  };
  std::vector<Carried> carried;
  bool any = false, any_held_or_rigid = false, any_near_walls = false;
  bool held(int mask) const { return (mask & held_bits) || (any_integrator && !(mask & integrated_bits)); }
};

// The smallest radius of the atoms of a group over all ranks, at a run's set-up, after refusing
// a point particle (diameter 0: no contact surface and no film, R = 0 in 1/eps) with an ERROR
// naming the atom (style: the command's name for the message).
double smallest_sphere_radius(LAMMPS *lmp, const char *style, int groupbit);

}    // namespace LAMMPS_NS

#endif
