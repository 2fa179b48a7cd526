// The step velocities of `model lubricated` in LIGGGHTS 3.8.0 at a run's set-up (issue 18): the
// twin of the LAMMPS plugin's fix LUBRICATED_STEP_VELOCITY (src/fix_step_velocity).
//
// A step evaluates the contacts with velocity Verlet's v^(n-1/2) (doc/model.rst, "Time
// integration"); a set-up has only v^n = v^(n-1/2) + dt/2 f^n / m. This fix keeps each atom's
// last half kick dt/2 f/m at the end of a run that took steps of fix nve/sphere (post_run, while
// f is the last step's), carries it with migrating atoms and into restart files, and at the next
// set-up sends it to the ghosts; the model then evaluates with u_n - (kick_i - kick_j) . n as a
// step, so split runs, `run 0` and restarts give the uninterrupted run's normal forces.
// LIGGGHTS's own tangential and rolling models still see the full-step velocities.
//
// The model's pair and wall models create it (ID lubricated_step_velocity) at their init.
//
// It also watches the smallest radius for the models with a grid spacing, whose film reach
// (0.75 dx) is a contact distance factor of the smallest sphere: a smaller one that appears
// during a run (fix insert) is reported to them before the neighbor list is built.
#pragma once

#include "fix.h"
#include "update.h"

#include <functional>

namespace lubricated {
namespace liggghts {

// A model (key: its address, never dereferenced) whose contact distance covers the radii from
// `covered` up: smaller(r) is called on every rank when the smallest radius r < covered first
// appears at a neighbor list build of lmp (then covered = r). The model forgets itself when it
// is destroyed; the registry outlives the fixes.
void watch_radius(LAMMPS_NS::LAMMPS *lmp, const void *model, double covered, std::function<void(double)> smaller);
void forget_radius(const void *model);

class FixLubricatedStepVelocity : public LAMMPS_NS::Fix {
 public:
  static constexpr const char *id_name = "lubricated_step_velocity";
  static constexpr const char *style_name = "lubricated/step_velocity";
  static FixLubricatedStepVelocity *find_or_create(LAMMPS_NS::LAMMPS *lmp);

  FixLubricatedStepVelocity(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
  ~FixLubricatedStepVelocity() override;
  int setmask() override;
  void pre_neighbor() override;
  void setup_pre_neighbor() override;
  void post_run() override;

  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  int pack_exchange(int i, double *buf) override;
  int unpack_exchange(int nlocal, double *buf) override;
  int pack_restart(int i, double *buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_restart(FILE *fp) override;
  void restart(char *buf) override;
  int pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) override;
  void unpack_comm(int n, int first, double *buf) override;
  double memory_usage() override;

  // Whether this set-up continues the last run's steps (inline: asked for every pair).
  bool continues() const { return continuing_ && update->setupflag; }
  // (kick_i - kick_j) . n, the part of the full-step u_n the last half kick added (j < 0: a wall).
  double kick_along(int i, int j, const double *n) const
  {
    const double *ki = kick_[i];
    const double d0 = j < 0 ? ki[0] : ki[0] - kick_[j][0], d1 = j < 0 ? ki[1] : ki[1] - kick_[j][1],
                 d2 = j < 0 ? ki[2] : ki[2] - kick_[j][2];
    return d0 * n[0] + d1 * n[1] + d2 * n[2];
  }

 private:
  double **kick_ = nullptr;     // per atom (owned, and ghosts at a set-up): dt/2 f/m of the last step
  bool continuable_ = false;    // the last run ended with a step of fix nve/sphere
  bool continuing_ = false;     // this set-up continues it
  double step_dt_ = 0.0;        // the time step of that step
  int integrated_bits_ = 0;     // the groups of the fixes nve/sphere
  bool integrated_by_nve_sphere();
  void check_radii();
};

}    // namespace liggghts
}    // namespace lubricated
