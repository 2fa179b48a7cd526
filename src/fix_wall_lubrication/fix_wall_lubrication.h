/* -*- c++ -*- ----------------------------------------------------------
   fix wall/lubrication: planar or cylindrical walls, at rest or moving, with the
   spring-dashpot contact and the particle-wall lubrication film of Brandle de Motta et al.
   (CFM 2011). The same kernel as pair_style lubricated/springdashpot, with m_e = m and
   lambda_pw (at a curved wall with the film radius R_f, lubricated/wall_curvature.h).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_WALL_LUBRICATION_H
#define LMP_FIX_WALL_LUBRICATION_H

#include "fix.h"

#include "contact_mass/contact_mass.h"
#include "lubricated/contact.h"
#include "lubricated/wall_geometry.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixWallLubrication : public Fix {
 public:
  FixWallLubrication(class LAMMPS *, int, char **);
  ~FixWallLubrication() override;

  void post_constructor() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void min_setup(int) override;
  void pre_force(int) override;
  void post_force(int) override;
  void min_post_force(int) override;
  void reset_dt() override;
  double compute_scalar() override;
  double compute_vector(int) override;
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

  bool wet() const { return coeffs.wet(); }
  // Adds this step's wall-film shares to the owned atoms' loads of the many-body film budget
  // (lubricated/film_budget.h; pair_style lubricated/springdashpot sums them with its own).
  void add_film_loads(double *load, int nlocal) const;
  // Adds to each owned atom the bound on its wet walls' film shares (film_budget.h).
  void add_film_share_bounds(double *bound, int nlocal) const;

 protected:
  lubricated::Coefficients coeffs;
  lubricated::ContactModel model;    // derived from coeffs and dt
  // Per atom and wall (lo or the cylinder, hi): elongation x y z and a touched flag.
  static constexpr int HISTORY_PER_WALL = 4, HISTORY_SIZE = 2 * HISTORY_PER_WALL;
  double **history = nullptr;
  bool keeps_history() const { return coeffs.friction > 0.0; }
  std::vector<lubricated::WallSurface> walls;    // lo (or the cylinder), hi; history slots 0, 1
  std::vector<int> slots;                        // each wall's history slot
  lubricated::WallMotion motion;
  // The motion's clock: time since the fix was defined = elapsed + (step - step_origin) motion_dt,
  // rebased when the time step changes; in the restart file, so that a restarted run moves on.
  double elapsed = 0.0, motion_dt = 0.0;
  bigint step_origin = 0;
  double wall_time() const;
  void rebase_clock();
  std::string describe_walls() const;
  void parse_walls(int narg, char **arg, int iwall);
  void parse_motion(int narg, char **arg, int iarg);
  void check_sphere_sizes();
  double local_sums[4] = {0.0, 0.0, 0.0, 0.0};    // energy, force on the group x y z
  double global_sums[4] = {0.0, 0.0, 0.0, 0.0};
  bool sums_reduced = false;
  class FixNVESphereMidpoint *midpoint = nullptr;    // the paper's integrator, if in use
  class FixStepVelocity *step_velocity = nullptr;    // the last step's velocities for a set-up
  // A run computes the walls in pre_force, before the pair style, and applies their films in
  // post_force, scaled by the atoms' film budget: per owned atom, the wall films' force along
  // x y z and their summed share (valid while films_pending).
  class PairLubricatedSpringDashpot *pair = nullptr;
  std::vector<double> film_force, film_load;
  // With the shear film: per owned atom, its force x y z and torque x y z (both walls), deferred
  // and scaled with the normal films (one contact's share: the larger of the two films').
  std::vector<double> shear_film;
  bool shear_pending = false;
  bool films_pending = false;
  // Immovable atoms (skipped: the wall cannot move them) and rigid bodies (m_e = M_body).
  ContactMass contact_mass;
  std::vector<double> inverse_mass;
  void compute_walls(bool defer_films);
  void warn_behind();
  void apply_films();
};

}    // namespace LAMMPS_NS

#endif
