/* -*- c++ -*- ----------------------------------------------------------
   fix fluid/drag: the unresolved fluid acting on finite-size spheres: drag from the slip
   velocity (Stokes or Schiller-Naumann), hindered settling from the local solid fraction
   (Richardson-Zaki or Di Felice) and buoyancy; optionally the fluid's inertia and memory
   (added mass, undisturbed-flow force, Basset history, Magnus and Saffman lift) and the
   Stokes torque on the spin. Physics in
   src/lubricated/drag.h and src/lubricated/fluid_inertia.h. Keywords parsed in
   fix_fluid_drag_args.cpp, the force per atom in fix_fluid_drag_force.cpp, the per-atom
   history in fix_fluid_drag_history.cpp.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_FLUID_DRAG_H
#define LMP_FIX_FLUID_DRAG_H

#include "fix.h"

#include "film_budget/implicit_drag.h"

#include "lubricated/drag.h"
#include "lubricated/fluid_inertia.h"
#include "lubricated/wall_added_mass.h"
#include "lubricated/history_kernel.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixFluidDrag : public Fix, public ImplicitDragParticipant {
 public:
  FixFluidDrag(class LAMMPS *, int, char **);
  ~FixFluidDrag() override;

  int setmask() override;
  void init() override;
  void setup(int) override;
  void pre_force(int) override;
  void post_force(int) override;
  double compute_vector(int) override;
  double memory_usage() override;

  // C_m and rho_f of the added mass m_a = C_m (rho_f V) (C_m 0 without added_mass). The contacts
  // of the plugin's styles move m + m_a (contact_mass.h), as this fix's solve does.
  double added_mass_coefficient() const { return added_mass; }
  double fluid_density() const { return model.density; }
  const std::vector<lubricated::AddedMassWall> &near_walls() const { return added_mass_walls; }    // keyword wall

  // The drag and torque taken implicitly by the pair style's coupled film solve
  // (film_budget/implicit_drag.h; fix_fluid_drag_force.cpp).
  bool drag_is_implicit() override;
  LinearDrag linear_drag(int i, const double *v) override;
  void take_increments(const double *increments, int nlocal, bigint step) override;

  // the Basset history per atom (fix_fluid_drag_history.cpp)
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

 protected:
  friend struct FluidDragKeywords;    // the keyword table (fix_fluid_drag_args.cpp)
  friend struct FluidDragValues;
  class FixStepVelocity *step_velocity = nullptr;    // the last step's velocities for a set-up
  lubricated::DragModel model;
  struct Component {
    double value = 0.0;    // constant, or the last value of an equal-style variable
    std::string name;      // variable name ("" for a constant)
    int ivar = -1;
    bool per_atom = false;
  };
  Component velocity[3], acceleration[3], vorticity[3];    // u_f, Du_f/Dt, curl u_f
  bool velocity_given = false, acceleration_given = false, vorticity_given = false;
  bool affine_flow = false;    // flow affine: u_f the deforming box's affine velocity
  bool have_viscosity = false;
  bool superficial = false;
  double gravity[3] = {0.0, 0.0, 0.0};    // for buoyancy; zero vector: none
  int nbins[3] = {1, 1, 1};
  static constexpr double max_bins = 1e8;    // nx ny nz: 1.6 GB of bins on every rank
  bool bins_given = false;
  int every = 1;    // phi at the steps that are multiples of every (kept between runs)

  // fluid inertia and memory (all off by default)
  double added_mass = 0.0;                                    // C_m
  std::vector<lubricated::AddedMassWall> added_mass_walls;    // its near-wall increase
  bool pressure = false;                                      // rho_f V Du_f/Dt
  bool history = false;                                       // Basset-Boussinesq
  bool magnus = false;                                        // Rubinow-Keller lift
  bool saffman = false;                                       // Saffman-Mei shear lift
  bool rotation = false;                                      // Stokes torque on the spin
  int history_window = 10, history_modes = 20;
  lubricated::BassetHistory basset;
  bool finite_re = false;    // kernel mei-adrian (history_kernel.h) instead of Basset's
  lubricated::MeiAdrianKernel mei_adrian;
  double **history_state = nullptr;
  double history_dt = 0.0;       // the step the tail is laid out for
  bool history_begun = false;    // a step has been committed (or restored): the layout is kept
  bool stiff_warned = false;     // beta dt / (m + m_a + m_h) > 1 was reported
  // steps of unequal length (fix_fluid_drag_history.cpp): the lengths of the window's steps
  lubricated::HistorySteps history_steps;
  double evaluated_dt = 0.0;    // the step that ended at the last evaluation kept (0: none yet)
  bool steps_uniform = true;    // this step and the window's all that of the layout
  std::vector<double> step_bound, step_weight, step_decay, step_feed;

  std::vector<double> bin_solid;    // solid volume fraction per bin
  std::vector<double> local_sum;
  double *atom_velocity[3] = {nullptr, nullptr, nullptr};
  double *atom_acceleration[3] = {nullptr, nullptr, nullptr};
  double *atom_vorticity[3] = {nullptr, nullptr, nullptr};
  int maxatom = 0;
  bigint last_fraction_step = -1;
  double totals[4] = {0.0, 0.0, 0.0, 0.0}, totals_all[4] = {0.0, 0.0, 0.0, 0.0};
  // The solve's increments of the owned atoms (6 each) at step solved_step, where it took the drag.
  std::vector<double> solved_increments;
  bigint solved_step = -1;
  bool totals_reduced = false;

  void parse(int narg, char **arg);
  void check_keywords();
  bool needs_fraction() const;
  void refresh_solid_fraction();    // this step's phi, where due (at multiples of every) and not yet made
  // The fluid's velocity, acceleration and vorticity of this step (constants or variables), once
  // a step (again at a set-up: the variables may have changed between runs).
  bigint fluid_fields_step = -1;
  void evaluate_fluid_fields();
  bool fluid_inertia() const { return added_mass > 0.0 || pressure || history || magnus || saffman; }
  bool solves_acceleration() const { return added_mass > 0.0 || history; }
  void check_last_force_fix();
  void evaluate(Component *components, double **per_atom);
  // Cloud-in-cell weights: up to 8 bins around x and their trilinear weights.
  int cloud_in_cell(const double *x, int *bins, double *weights) const;
  double solid_fraction_at(const double *x) const;
  void update_solid_fraction();
  bool stores_fraction() const { return needs_fraction() && every > 1; }
  // the force per atom (fix_fluid_drag_force.cpp)
  struct Slip {
    double voidage, fluid_scale;              // eps = 1 - phi; u_f's factor (1 / eps where superficial)
    double w[3], speed;                       // slip u_f - v and its magnitude
    double diameter, beta, buoyant_volume;    // d, the drag coefficient, rho_f V
  };
  Slip slip_at(int i, const double *v) const;
  void apply_drag(int i, const Slip &s, const double *solved);
  void apply_with_inertia(int i, const Slip &s, const double *omega, const double *solved);
  double history_force(int i, const Slip &s, double *known);
  double history_mass(int i, const Slip &s);
  struct HistoryWeights {
    const double *window, *tail;
  };
  HistoryWeights history_weights(const Slip &s);
  void near_wall_added_mass(int i, const Slip &s, double m_a, double *axis_mass, double *wall_force) const;
  void lift_force(int i, const Slip &s, const double *omega, double *lift) const;
  void apply_rotation(int i, const double *omega, const double *solved);
  void fluid_vorticity(int i, double *curl) const;
  void fluid_velocity(int i, double *u) const;
  void record(int i, const double *force);
  void setup_history();
  void lay_out_tail(double dt);
  void weigh_history_steps();
  void warn_stiff_history();
};

}    // namespace LAMMPS_NS

#endif
