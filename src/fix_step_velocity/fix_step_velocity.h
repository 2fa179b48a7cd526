/* -*- c++ -*- ----------------------------------------------------------
   fix LUBRICATED_STEP_VELOCITY: lets a run continue the last one exactly. Internal: the pair
   style and fix wall/lubrication create it (one, shared) in their init.

   A step evaluates the contacts with the velocities of the last step, velocity Verlet's
   v^(n-1/2) (doc/model.rst, "Time integration"); the set-up of a run has only the full-step
   v^n = v^(n-1/2) + dt/2 f^n / m. Where the last run ended with a step of fix nve/sphere,
   this fix restores v^(n-1/2) and omega^(n-1/2) at the next run's set-up, and
   the set-up evaluates as the step did: the same forces, so a split run, `run 0` and a
   restart continue as the uninterrupted run. The last half kicks are kept at the end of each run
   that took steps (post_run, while the forces are the last step's); they travel with migrating
   atoms and into restart files, and the set-up computes v - kick after its migration (for the
   ghosts too).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_STEP_VELOCITY_H
#define LMP_FIX_STEP_VELOCITY_H

#include "fix.h"
#include "update.h"

namespace LAMMPS_NS {

class FixStepVelocity : public Fix {
 public:
  static constexpr const char *ID = "LUBRICATED_STEP_VELOCITY";
  // The one instance, created on first use by the pair style or a wall fix.
  static FixStepVelocity *find_or_create(class LAMMPS *lmp);

  FixStepVelocity(class LAMMPS *, int, char **);
  ~FixStepVelocity() override;

  int setmask() override;
  void post_neighbor() override {}
  void setup_post_neighbor() override;
  void post_run() override;
  void initial_integrate(int) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

  // Whether this set-up continues the last run's steps; then the last step's velocities of
  // owned and ghost atoms (nmax x 3, contiguous like atom->v and atom->omega).
  bool continues() const { return continuing && update->setupflag; }
  // Whether fix nve/sphere is the run's only time integration (the scheme the kicks undo).
  bool integrated_by_nve_sphere() const;
  double **velocity() { return vhalf; }
  double **spin() { return whalf; }

 protected:
  double **kick = nullptr;    // per atom: last half kick of v and omega
  // Owned and ghost: the velocities of a set-up that continues a run, until its first step.
  double **vhalf = nullptr, **whalf = nullptr;
  void release_setup_velocities();
  void hold_kicks(bool hold);
  bool continuable = false;    // the last run ended with a step of fix nve/sphere
  bool continuing = false;     // this set-up continues it
  double step_dt = 0.0;        // the time step of those steps
  void store_kick(int i);
};

}    // namespace LAMMPS_NS

#endif
