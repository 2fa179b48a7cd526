/* -*- c++ -*- ----------------------------------------------------------
   fix nve/sphere/midpoint: the time integration of Brandle de Motta et al. (CFM 2011),
   eqs. (1)-(3) with the second-order extrapolation V~ = 3/2 V^n - 1/2 V^(n-1) (doc/model.rst,
   "The paper's time scheme"). Forces are evaluated at the predicted mid-step state; usable
   instead of fix nve/sphere. Keeps V^(n-1) (and omega^(n-1)) per atom, through migration and restarts.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_NVE_SPHERE_MIDPOINT_H
#define LMP_FIX_NVE_SPHERE_MIDPOINT_H

#include "fix.h"

namespace LAMMPS_NS {

class FixNVESphereMidpoint : public Fix {
 public:
  FixNVESphereMidpoint(class LAMMPS *, int, char **);
  ~FixNVESphereMidpoint() override;

  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void reset_dt() override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 public:
  // The instance whose step velocities the contact styles take (`who`, for the message), or
  // nullptr where there is none. Its rows hold the step velocity of the atoms it integrates;
  // another time integration beside it (fix nve/sphere, rigid, move, a second instance) moves
  // atoms whose rows keep their set-up velocity, which their contacts would take: an ERROR.
  static FixNVESphereMidpoint *in_use(class LAMMPS *lmp, const char *who);

  // V^n of owned and ghost atoms during a step: the velocity over the last step of the
  // force-evaluation points X~ (X~^n - X~^(n-1) = dt V^n), which the step-exact contact of
  // pair_style lubricated/springdashpot needs in place of the extrapolated V~.
  const double *step_velocity(int i) const { return state[i] + 6; }
  // The same as one block: atom i's from step_velocities() + step_velocity_stride() i (at least
  // one atom allocated).
  const double *step_velocities() const { return state[0] + 6; }
  static int step_velocity_stride() { return NVALUES; }

 protected:
  // Per atom: 0-2 V^(n-1), 3-5 omega^(n-1) between steps; 6-8 V^n, 9-11 omega^n within one;
  // 12 non-zero until the atom's first step is done. Restart: a count, 0-5, 12.
  static constexpr int FIRST_STEP = 12, NVALUES = 13, RESTART_SIZE = 8;
  double **state = nullptr;
  double dt = 0.0;
};

}    // namespace LAMMPS_NS

#endif
