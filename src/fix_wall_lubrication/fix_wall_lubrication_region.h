/* -*- c++ -*- ----------------------------------------------------------
   fix wall/lubrication/region: the wall of fix wall/lubrication on the surface of any LAMMPS
   region, static, moving or rotating (doc/fix_wall_lubrication_region.rst). The contact and
   film act on the sphere's motion relative to the region's surface at the contact point; the
   film takes the radius R_f of the curved surface (lubricated/wall_curvature.h); friction
   history is kept per atom and per region face, migrates and is written to restart files.
   This class finds the contacts with the region's faces; the base applies each.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_WALL_LUBRICATION_REGION_H
#define LMP_FIX_WALL_LUBRICATION_REGION_H

#include "fix_wall_lubrication_base.h"
#include "lubricated/wall_motion.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixWallLubricationRegion : public FixWallLubricationBase {
 public:
  FixWallLubricationRegion(class LAMMPS *, int, char **);
  ~FixWallLubricationRegion() override;

  void init() override;
  void reset_dt() override;

  // Per-atom friction history per region face (fix_wall_lubrication_region_history.cpp).
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;
  // The region's motion of the last step (for a run that continues across a restart).
  void write_restart(FILE *) override;
  void restart(char *) override;

  void add_film_share_bounds(double *bound, int nlocal) const override;

  // Largest film radius against a concave surface, in sphere radii: R_f <= 4 R keeps the
  // search cutoff and the budget's bounds finite (a sphere region of radius >= 4/3 R, a
  // cylinder of radius >= 16/15 R); a wet sphere nearly filling a concave region is an error.
  static constexpr double MAX_FILM_RATIO = 4.0;

 protected:
  std::string region_id;
  class Region *region = nullptr;
  enum class Shape { flat, sphere, cylinder } shape = Shape::flat;    // how contact radii read

  // The region's rigid motion over the last step, from its displacement and angle (public
  // members of Region) differenced over the step; kept for a set-up that continues the run.
  lubricated::RigidWallMotion motion;
  double last_displacement[4] = {0.0, 0.0, 0.0, 0.0};    // dx dy dz theta at last_step
  bigint last_step = -1;
  void update_motion();

  // Per atom: tmax slots of [face id + 1 (0: free), elongation x y z, touched flag].
  static constexpr int SLOT = 5;
  int slots = 0;    // region->tmax
  double **history = nullptr;
  bool keeps_history() const { return coeffs.friction > 0.0; }
  std::vector<int> faces;    // the faces near the atom being evaluated
  // Gravity's steady load on each face near the atom being evaluated, shared among the faces it
  // overlaps (share_face_loads), with the faces' normals and gaps.
  std::vector<double> face_load, face_gap;
  std::vector<lubricated::Vec3> face_normal;
  void share_face_loads(int i, int nc);
  double *history_slot(int i, int face);    // its slot, taken (zeroed) when it has none
  void forget_slot(int i, int face);
  void release_other_slots(int i, const int *near, int n);

  // energy, force of the wall on the group x y z, its torque about the reference point x y z
  void add_to_sums(const double *x, const lubricated::Vec3 &force, const lubricated::Vec3 &torque);

  void find_contacts() override;
  void tally(int i, const lubricated::Vec3 &force, const lubricated::Vec3 &torque) override;
  void contacts_of_atom(int i, double mass);
  int faces_near(int i, const double *vi);
  void face_contact(int i, double mass, int ic, const double *vi);
  lubricated::FilmRadius film_radius(double sphere_radius, double contact_radius) const;
};

}    // namespace LAMMPS_NS

#endif
