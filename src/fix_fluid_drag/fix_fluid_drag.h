/* -*- c++ -*- ----------------------------------------------------------
   fix fluid/drag: the unresolved fluid acting on finite-size spheres: drag from the slip
   velocity (Stokes or Schiller-Naumann), hindered settling from the local solid fraction
   (Richardson-Zaki or Di Felice) and buoyancy. Physics in src/lubricated/drag.h.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_FLUID_DRAG_H
#define LMP_FIX_FLUID_DRAG_H

#include "fix.h"

#include "lubricated/drag.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixFluidDrag : public Fix {
 public:
  FixFluidDrag(class LAMMPS *, int, char **);
  ~FixFluidDrag() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;
  double memory_usage() override;

 protected:
  class FixStepVelocity *step_velocity = nullptr;    // the last step's velocities for a set-up
  lubricated::DragModel model;
  struct Component {
    double value = 0.0;    // constant, or the last value of an equal-style variable
    std::string name;      // variable name ("" for a constant)
    int ivar = -1;
    bool per_atom = false;
  } velocity[3];
  bool superficial = false;
  double gravity[3] = {0.0, 0.0, 0.0};    // for buoyancy; zero vector: none
  int nbins[3] = {1, 1, 1};
  bool bins_given = false;
  int every = 1;

  std::vector<double> bin_solid;    // solid volume fraction per bin
  std::vector<double> local_sum;
  double *atom_velocity[3] = {nullptr, nullptr, nullptr};
  int maxatom = 0;
  bigint last_fraction_step = -1;
  double totals[4] = {0.0, 0.0, 0.0, 0.0}, totals_all[4] = {0.0, 0.0, 0.0, 0.0};
  bool totals_reduced = false;

  bool needs_fraction() const;
  // Cloud-in-cell weights: up to 8 bins around x and their trilinear weights.
  int cloud_in_cell(const double *x, int *bins, double *weights) const;
  double solid_fraction_at(const double *x) const;
  void update_solid_fraction();
};

}    // namespace LAMMPS_NS

#endif
