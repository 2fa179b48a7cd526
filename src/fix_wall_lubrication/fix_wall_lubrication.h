/* -*- c++ -*- ----------------------------------------------------------
   fix wall/lubrication: planar walls with the spring-dashpot contact and the
   particle-wall lubrication film of Brandle de Motta et al. (CFM 2011).
   The same kernel as pair_style lubricated/springdashpot, with m_e = m and lambda_pw.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_WALL_LUBRICATION_H
#define LMP_FIX_WALL_LUBRICATION_H

#include "fix.h"

#include "lubricated/normal_model.h"

namespace LAMMPS_NS {

class FixWallLubrication : public Fix {
 public:
  FixWallLubrication(class LAMMPS *, int, char **);

  int setmask() override;
  void init() override;
  void setup(int) override;
  void min_setup(int) override;
  void post_force(int) override;
  void min_post_force(int) override;
  void reset_dt() override;
  double compute_scalar() override;
  double compute_vector(int) override;

 protected:
  lubricated::Coefficients coeffs;
  lubricated::NormalModel model;
  int axis = -1;                  // 0, 1, 2 for xplane, yplane, zplane
  bool has_lo = false, has_hi = false;
  double lo = 0.0, hi = 0.0;      // wall positions (box units)
  double local_sums[4] = {0.0, 0.0, 0.0, 0.0};    // energy, force on the group x y z
  double global_sums[4] = {0.0, 0.0, 0.0, 0.0};
  bool sums_reduced = false;
  class FixNVESphereMidpoint *midpoint = nullptr;    // the paper's integrator, if in use
};

}    // namespace LAMMPS_NS

#endif
