/* -*- c++ -*- ----------------------------------------------------------
   fix wall/lubrication: planar or cylindrical walls, at rest or moving, with the
   spring-dashpot contact and the particle-wall lubrication film of Brandle de Motta et al.
   (CFM 2011). The same kernel as pair_style lubricated/springdashpot, with m_e = m and
   lambda_pw (at a curved wall with the film radius R_f, lubricated/wall_curvature.h).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_WALL_LUBRICATION_H
#define LMP_FIX_WALL_LUBRICATION_H

#include "fix_lubricated_wall/fix_lubricated_wall.h"
#include "lubricated/wall_geometry.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixWallLubrication : public FixLubricatedWall {
 public:
  FixWallLubrication(class LAMMPS *, int, char **);
  ~FixWallLubrication() override;

  void init() override;
  void reset_dt() override;
  // The wall motion's time origin (global restart), so that a restarted run moves on.
  void write_restart(FILE *) override;
  void restart(char *) override;

  // Per-atom tangential elongation at each wall (friction only): migrates, restarts.
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

  void add_film_share_bounds(double *bound, int nlocal) const override;

 protected:
  // Per atom and wall (lo or the cylinder, hi; only the walls given, slot k for walls[k]):
  // elongation x y z and a touched flag. Restart files before this layout held two slots (lo 0,
  // hi 1, LEGACY_HISTORY_SIZE values) whatever the walls; unpack_restart reads both.
  static constexpr int HISTORY_PER_WALL = 4, LEGACY_HISTORY_SIZE = 2 * HISTORY_PER_WALL;
  int history_size = 0;    // HISTORY_PER_WALL per wall
  double **history = nullptr;
  bool keeps_history() const { return coeffs.friction > 0.0; }
  std::vector<lubricated::WallSurface> walls;    // lo (or the cylinder), hi
  std::vector<int> legacy_slots;                 // each wall's slot in the two-slot layout
  lubricated::WallMotion motion;
  // The motion's clock: time since the fix was defined = elapsed + (step - step_origin) motion_dt,
  // rebased when the time step changes; in the restart file, so that a restarted run moves on.
  double elapsed = 0.0, motion_dt = 0.0;
  bigint step_origin = 0;
  double cavitation = -1.0;    // tension limit dp_c of a separating film (< 0: none; film_cavitation.h)
  double wall_time() const;
  void rebase_clock();
  std::string describe_walls() const;
  void parse_walls(int narg, char **arg, int iwall);
  void parse_motion(int narg, char **arg, int iarg);
  void check_sphere_sizes();
  void compute_walls(bool defer_films) override;
  void tally_film(int i, const lubricated::Vec3 &force, const lubricated::Vec3 &moment) override;
  void warn_behind();
};

}    // namespace LAMMPS_NS

#endif
