/* ----------------------------------------------------------------------
   fix fluid/drag: the force on each atom of the group (see doc/fix_fluid_drag.rst), in steps:
   the fluid at the atom and its slip, then either the drag alone or the Maxey-Riley-Gatignol
   solve with the fluid's inertia and memory (src/lubricated/fluid_inertia.h).
------------------------------------------------------------------------- */

#include "fix_fluid_drag.h"

#include "fix_step_velocity/fix_step_velocity.h"

#include "atom.h"
#include "domain.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
namespace lub = lubricated;

void FixFluidDrag::post_force(int vflag)
{
  v_init(vflag);    // the virial, where fix_modify virial yes asks for it
  refresh_solid_fraction();

  evaluate_fluid_fields();
  if (history) weigh_history_steps();

  // A set-up that continues the last run drags with the velocities of its last step, as that
  // step did (fix_step_velocity.h, kept where the pair style or a wall fix of this plugin is).
  const bool continued = step_velocity && step_velocity->continues();
  double **v = continued ? step_velocity->velocity() : atom->v;
  double **omega = continued ? step_velocity->spin() : atom->omega;
  for (double &t : totals)
    t = 0.0;
  totals_reduced = false;

  // Where the pair style's film solve took the drag this evaluation, its increments x
  // (implicit_drag.h; init() forgets those of the last run).
  const double *solved = solved_step == update->ntimestep ? solved_increments.data() : nullptr;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const Slip slip = slip_at(i, v[i]);
    const double *x = solved ? solved + 6 * i : nullptr;
    if (fluid_inertia())
      apply_with_inertia(i, slip, omega[i], x);
    else
      apply_drag(i, slip, x);
    if (rotation) apply_rotation(i, omega[i], x ? x + 3 : nullptr);
  }
}

// At multiples of every (LAMMPS's convention), so that split runs and restarts see the same phi
// as one run; in between, the last one, also from the last run or a restart file. Once a step:
// the film solve may have made it already (drag_is_implicit). The positions do not change
// between the pair style and the fixes' forces.
void FixFluidDrag::refresh_solid_fraction()
{
  if (!needs_fraction() || last_fraction_step == update->ntimestep) return;
  if (last_fraction_step < 0 || update->ntimestep % every == 0) update_solid_fraction();
}

// Fluid velocity, acceleration and vorticity: constants, equal-style or atom-style variables.
void FixFluidDrag::evaluate_fluid_fields()
{
  if (fluid_fields_step == update->ntimestep && !update->setupflag) return;
  evaluate(velocity, atom_velocity);
  if (fluid_inertia()) evaluate(acceleration, atom_acceleration);
  if (magnus || saffman || rotation) evaluate(vorticity, atom_vorticity);
  fluid_fields_step = update->ntimestep;
}

// The coupled film solve may take the drag (linear in v), not at a set-up unless it continues the
// last run's steps (fix_step_velocity.h: it then evaluates as the last step did), and not where
// the added mass grows near walls (a mass per axis). With the fluid's inertia the solve moves the
// mass this fix solves for. The step's solid fraction (bins) and fluid velocity and vorticity
// (variables) and the history's weights are made here, before the solve reads them, and kept
// for post_force.
bool FixFluidDrag::drag_is_implicit()
{
  const bool continued = step_velocity && step_velocity->continues();
  if ((update->setupflag && !continued) || !added_mass_walls.empty()) return false;
  refresh_solid_fraction();
  evaluate_fluid_fields();
  if (history) weigh_history_steps();    // this step's weights, for the mass the solve moves
  return true;
}

FixFluidDrag::LinearDrag FixFluidDrag::linear_drag(int i, const double *v)
{
  LinearDrag d;
  if (!(atom->mask[i] & groupbit)) return d;
  const Slip s = slip_at(i, v);
  d.drag = s.beta;
  for (int c = 0; c < 3; c++)
    d.fluid_velocity[c] = s.w[c] + v[c];
  if (history) d.solved_mass = history_mass(i, s);    // the added mass is in the contact mass
  if (!rotation) return d;
  d.rotational_drag = lub::rotational_drag_coefficient(atom->radius[i], model.viscosity);
  double curl[3];
  fluid_vorticity(i, curl);
  for (int c = 0; c < 3; c++)
    d.fluid_spin[c] = 0.5 * curl[c];
  return d;
}

void FixFluidDrag::take_increments(const double *increments, int nlocal, bigint step)
{
  solved_increments.assign(increments, increments + 6 * nlocal);
  solved_step = step;
}

// The fluid velocity at atom i (scaled to the interstitial one where it is superficial), the
// slip and the drag coefficient there.
FixFluidDrag::Slip FixFluidDrag::slip_at(int i, const double *v) const
{
  Slip s;
  s.voidage = needs_fraction() ? 1.0 - solid_fraction_at(atom->x[i]) : 1.0;
  s.fluid_scale = superficial ? 1.0 / std::max(s.voidage, model.min_voidage) : 1.0;
  double speed2 = 0.0, u[3];
  fluid_velocity(i, u);
  for (int d = 0; d < 3; d++) {
    s.w[d] = u[d] * s.fluid_scale - v[d];
    speed2 += s.w[d] * s.w[d];
  }
  s.speed = std::sqrt(speed2);
  s.diameter = 2.0 * atom->radius[i];
  s.beta = lub::drag_beta(model, s.diameter, s.speed, s.voidage);
  s.buoyant_volume = model.density * lub::sphere_volume(atom->radius[i]);
  return s;
}

// The velocity keyword's constants or variables, or the affine velocity of the deforming box.
void FixFluidDrag::fluid_velocity(int i, double *u) const
{
  if (affine_flow) {
    double lamda[3];
    domain->x2lamda(atom->x[i], lamda);
    lub::affine_velocity(domain->h_rate, domain->h_ratelo, lamda, u);
    return;
  }
  for (int d = 0; d < 3; d++)
    u[d] = velocity[d].per_atom ? atom_velocity[d][i] : velocity[d].value;
}

// Drag and buoyancy alone. Explicit relaxation is stable and exact in steady state while
// beta dt / m <= 1; beyond, the drag removes the slip in one step and never reverses it. Where
// the film solve took the drag (solved: its increment x of atom i), the drag at w + x.
void FixFluidDrag::apply_drag(int i, const Slip &s, const double *solved)
{
  const double beta = solved ? s.beta : std::min(s.beta, atom->rmass[i] / update->dt);
  double force[3];
  for (int d = 0; d < 3; d++) {
    force[d] = beta * (s.w[d] - (solved ? solved[d] : 0.0)) - s.buoyant_volume * gravity[d];
    atom->f[i][d] += force[d];
  }
  record(i, force);
}

// Maxey-Riley-Gatignol (fluid_inertia.h): added mass m_a and the history's current step m_h
// are solved for with the total force F, (m + m_a + m_h) a = F + (m_a + m_h) Du/Dt + H. Where the
// film solve took the drag (solved: atom i's increment x), the drag at w + x, uncapped.
void FixFluidDrag::apply_with_inertia(int i, const Slip &s, const double *omega, const double *solved)
{
  double fluid_accel[3];
  for (int d = 0; d < 3; d++)
    fluid_accel[d] = s.fluid_scale * (acceleration[d].per_atom ? atom_acceleration[d][i] : acceleration[d].value);
  const double m_a = added_mass * s.buoyant_volume;
  double known[3] = {0.0, 0.0, 0.0};
  const double m_h = history ? history_force(i, s, known) : 0.0;
  double axis_mass[3] = {m_a, m_a, m_a}, wall_force[3] = {0.0, 0.0, 0.0};
  if (!added_mass_walls.empty()) near_wall_added_mass(i, s, m_a, axis_mass, wall_force);
  const double m_eff = atom->rmass[i] + std::min(axis_mass[0], std::min(axis_mass[1], axis_mass[2])) + m_h;
  const double beta = solved ? s.beta : std::min(s.beta, m_eff / update->dt);    // apply_drag's cap, for this mass
  double lift[3] = {0.0, 0.0, 0.0};
  if (magnus || saffman) lift_force(i, s, omega, lift);
  const double undisturbed = pressure ? s.buoyant_volume : 0.0;
  double fluid[3];
  for (int d = 0; d < 3; d++)
    fluid[d] = beta * (s.w[d] - (solved ? solved[d] : 0.0)) - s.buoyant_volume * gravity[d] +
               undisturbed * fluid_accel[d] + lift[d] + wall_force[d];
  if (!solves_acceleration()) {
    for (int d = 0; d < 3; d++)
      atom->f[i][d] += fluid[d];
    record(i, fluid);
    return;
  }
  double *f = atom->f[i], accel[3], applied[3];
  const double mass = atom->rmass[i];
  for (int d = 0; d < 3; d++) {
    accel[d] = (f[d] + fluid[d] + known[d] + (axis_mass[d] + m_h) * fluid_accel[d]) / (mass + axis_mass[d] + m_h);
    const double total = mass * accel[d];
    applied[d] = total - f[d];
    f[d] = total;
  }
  record(i, applied);
  // A set-up keeps the last step's evaluation, which the next step commits: it is the end
  // value of that step, whereas the set-up's forces need not be the step's (nve/sphere/midpoint
  // evaluates at the mid-step point X~, V~ and ignores them). Only an atom's first end value
  // comes from a set-up.
  if (history && !(update->setupflag && history_state[i][0] > 1.5)) {
    const double wdot[3] = {fluid_accel[0] - accel[0], fluid_accel[1] - accel[1], fluid_accel[2] - accel[2]};
    lub::BassetHistory::store(history_state[i], wdot);
  }
}

// The history force's known part H and the weight m_h of this step's unknown acceleration.
double FixFluidDrag::history_force(int i, const Slip &s, double *known)
{
  const HistoryWeights w = history_weights(s);
  return basset.known_force(history_state[i], lub::basset_coefficient(s.diameter, model.density, model.viscosity),
                            update->dt, known, w.window, w.tail);
}

// The weight m_h alone, without the history's known part.
double FixFluidDrag::history_mass(int i, const Slip &s)
{
  return basset.current_weight(history_state[i], lub::basset_coefficient(s.diameter, model.density, model.viscosity),
                               update->dt, history_weights(s).window);
}

// The kernel's weights of this step (nullptr: Basset's for steps of one length): Basset's for
// steps of unequal length, or Mei-Adrian's for this step's slip speed.
FixFluidDrag::HistoryWeights FixFluidDrag::history_weights(const Slip &s)
{
  const double *window = steps_uniform ? nullptr : step_weight.data();    // steps of unequal length
  if (!finite_re) return {window, nullptr};
  mei_adrian.weigh(lub::mei_adrian_rate(s.speed, s.diameter, model.viscosity / model.density), update->dt,
                   steps_uniform ? nullptr : step_bound.data());
  return {mei_adrian.window(), mei_adrian.tail()};
}

// Near walls the added mass grows, per axis, and its change brings forces of its own
// (wall_added_mass.h), with the velocity relative to the fluid, -slip.
void FixFluidDrag::near_wall_added_mass(int i, const Slip &s, double m_a, double *axis_mass, double *wall_force) const
{
  const lub::WallAddedMass near = lub::wall_added_mass(
      added_mass_walls.data(), static_cast<int>(added_mass_walls.size()), atom->radius[i], atom->x[i]);
  const double relative[3] = {-s.w[0], -s.w[1], -s.w[2]};
  lub::wall_added_mass_force(near, m_a, relative, wall_force);
  for (int d = 0; d < 3; d++)
    axis_mass[d] = m_a * near.mass[d];
}

// The Stokes torque on the spin relative to the fluid's rotation (drag.h), backward Euler with
// the torques of the step so far (this fix is the last to add forces, init()); where the film
// solve took it (solved: the spin's increment), the torque at omega + x.
void FixFluidDrag::apply_rotation(int i, const double *omega, const double *solved)
{
  const double radius = atom->radius[i];
  const double inertia = 0.4 * atom->rmass[i] * radius * radius;
  double curl[3], spin_slip[3], torque[3];
  fluid_vorticity(i, curl);
  for (int d = 0; d < 3; d++)
    spin_slip[d] = 0.5 * curl[d] - omega[d] - (solved ? solved[d] : 0.0);
  if (solved) {
    const double beta_r = lub::rotational_drag_coefficient(radius, model.viscosity);
    for (int d = 0; d < 3; d++)
      atom->torque[i][d] += beta_r * spin_slip[d];
    return;
  }
  lub::implicit_drag_torque(lub::rotational_drag_coefficient(radius, model.viscosity), inertia, update->dt, spin_slip,
                            atom->torque[i], torque);
  for (int d = 0; d < 3; d++)
    atom->torque[i][d] += torque[d];
}

// The fluid's vorticity curl u_f at atom i: the vorticity keyword, else that of the deforming
// box's affine flow (flow affine), else none.
void FixFluidDrag::fluid_vorticity(int i, double *curl) const
{
  if (affine_flow && !vorticity_given) {
    lub::affine_vorticity(domain->h_rate, domain->h_inv, curl);
    return;
  }
  for (int d = 0; d < 3; d++)
    curl[d] = vorticity[d].per_atom ? atom_vorticity[d][i] : vorticity[d].value;
}

// Magnus lift (spin relative to the fluid's, omega - curl u / 2) and Saffman's shear lift.
void FixFluidDrag::lift_force(int i, const Slip &s, const double *omega, double *lift) const
{
  double curl[3], part[3];
  for (int d = 0; d < 3; d++)
    curl[d] = vorticity[d].per_atom ? atom_vorticity[d][i] : vorticity[d].value;
  if (magnus) {
    const double spin[3] = {omega[0] - 0.5 * curl[0], omega[1] - 0.5 * curl[1], omega[2] - 0.5 * curl[2]};
    lub::magnus_force(atom->radius[i], model.density, spin, s.w, part);
    for (int d = 0; d < 3; d++)
      lift[d] += part[d];
  }
  if (saffman) {
    lub::saffman_force(s.diameter, model.density, model.viscosity, s.w, curl, part);
    for (int d = 0; d < 3; d++)
      lift[d] += part[d];
  }
}

// The fluid's force on atom i, into the group's total and, on request, the virial: the force
// of an external field at the unwrapped position r, r_a F_b (Voigt order xx yy zz xy xz yz).
void FixFluidDrag::record(int i, const double *force)
{
  for (int d = 0; d < 3; d++)
    totals[d] += force[d];
  if (!vflag_either) return;
  double r[3];
  domain->unmap(atom->x[i], atom->image[i], r);
  double virial_i[6] = {force[0] * r[0], force[1] * r[1], force[2] * r[2],
                        force[0] * r[1], force[0] * r[2], force[1] * r[2]};
  v_tally(i, virial_i);
}
