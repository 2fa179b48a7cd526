/* -*- c++ -*- ----------------------------------------------------------
   The vectorised loops of pair style lubricated/springdashpot with tangential parts (friction,
   shear film), included by vector_pairs.cpp, whose entry points compile them per instruction
   set. Each law is the kernel's (lubricated/tangential.h: the slip, the tangential spring with
   its Coulomb cap, the shear film), inlined; the loops only select what a pair's state needs.
------------------------------------------------------------------------- */

#ifndef LMP_LUBRICATED_VECTOR_FRICTION_LOOPS_H
#define LMP_LUBRICATED_VECTOR_FRICTION_LOOPS_H

#include "lubricated/pair_geometry.h"
#include "vector_pairs.h"

namespace LAMMPS_NS {
namespace vector_pairs {

// RECORDS: whether the film budget's inputs are written (film, capacity, shear, slip_sq and
// tangential_mass); the force and torque always.
template <bool GRID, bool INVERSE, bool RECORDS> __attribute__((always_inline)) inline void
film_shear_only_loop(const Atoms &atoms, const lubricated::ContactModel &model, const int *__restrict pair_i,
                     const int *__restrict pair_j, int n, double *__restrict film_force, double *__restrict capacity,
                     double *__restrict force_x, double *__restrict force_y, double *__restrict force_z,
                     double *__restrict shear_x, double *__restrict shear_y, double *__restrict shear_z,
                     double *__restrict torque_x, double *__restrict torque_y, double *__restrict torque_z,
                     double *__restrict slip_sq, double *__restrict tangential_mass)
{
  namespace lub = lubricated;
  // The outputs as restrict parameters: restrict pointers read from a struct do not convince
  // GCC 12 that the stores do not alias (the loop then stays scalar). A local copy of the atoms'
  // pointers and of the model: no store can alias them, so their loads leave the loop.
  const Atoms local = atoms;
  const lub::Lubrication film_law = model.normal.lubrication;
  const lub::TangentialModel shear_law = model.tangential;
  const double dt = model.normal.step.dt, inv_dt = model.normal.step.inv_dt;
  for (int c = 0; c < n; c++) {
    const int i = pair_i[c], j = pair_j[c];
    const lub::PairGeometry g = lub::pair_geometry<INVERSE>(local, i, j);
    const double gap = g.r - g.radsum;
    double shear_log;    // the shear film's logarithm, from the normal film's
    const double film = lub::film_force_apart<GRID>(film_law, gap, g.film, g.m_e, g.u_n, dt, inv_dt, shear_log);
    const double normal = g.rinv * film;
    if (RECORDS) film_force[c] = film, capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    const double radi = local.radius[i], radj = local.radius[j];
    const lub::Vec3 n = lub::pair_normal(g);
    const lub::Vec3 s = lub::pair_slip(local, i, j, radi, radj, n);
    const double m_t = lub::tangential_mass_ratio * g.m_e;
    const double eps_al = film_law.activation_inline_eps<GRID>(g.film);
    const double damping = lub::shear_film_damping_of_log(shear_law, gap * g.film.inverse, eps_al, film_law.eps_release,
                                                          shear_log, radi * radj / g.radsum, m_t);
    const lub::Vec3 f{-damping * s.x, -damping * s.y, -damping * s.z};
    if (RECORDS) shear_x[c] = f.x, shear_y[c] = f.y, shear_z[c] = f.z;
    force_x[c] = g.delx * normal + f.x, force_y[c] = g.dely * normal + f.y, force_z[c] = g.delz * normal + f.z;
    // -n x F: the torque on i per unit of R_i (on j per unit of R_j).
    const lub::Vec3 nxf = lub::cross(n, f);
    torque_x[c] = -nxf.x, torque_y[c] = -nxf.y, torque_z[c] = -nxf.z;
    if (RECORDS) slip_sq[c] = lub::dot(s, s), tangential_mass[c] = m_t;
  }
}

// The normal part of a kept frictional pair (friction_contact_loop): the normal force (contact,
// film, energy), the films apart (film_apart), the shear film's logarithm, and the pair's state:
// on (1.0 where the lane is done here: resolved or in sustained contact or apart, r > 0 and
// m_e > 0), stick (the spring acts). EVENTS: contact_event_force (in overlap: the spring);
// else sustained_contact_force or film_force_apart as contact_or_film decides.
struct FrictionNormal {
  lubricated::NormalForce fn;
  double film_apart, shear_log, on;
  bool stick;
};
template <bool WET, bool GRID, bool EVENTS> __attribute__((always_inline)) inline FrictionNormal
friction_normal(const lubricated::NormalModel &normal, const lubricated::PairGeometry &g, double touched)
{
  namespace lub = lubricated;
  const double gap = g.r - g.radsum, dt = normal.step.dt, inv_dt = normal.step.inv_dt;
  FrictionNormal out;
  bool sustained = false, resolved = true;
  out.shear_log = 0.0;       // the shear film's logarithm, from the normal film's (WET)
  double lambda_al = 0.0;    // lambda(eps_al), from the film apart's (WET, not EVENTS)
  out.film_apart = WET & !EVENTS ? lub::film_force_apart<GRID>(normal.lubrication, gap, g.film, g.m_e, g.u_n, dt,
                                                               inv_dt, out.shear_log, lambda_al)
                                 : 0.0;
  // Dry: the film terms are 0 (six_pi_mu = 0).
  out.fn = EVENTS ? lub::contact_event_force<WET, GRID>(normal, gap, g.film, g.m_e, g.u_n, resolved, out.shear_log)
           : WET  ? lub::sustained_contact_force(normal, gap, g.film, g.m_e, g.u_n, lambda_al, sustained)
                  : lub::sustained_contact_force<GRID>(normal, gap, g.film, g.m_e, g.u_n, sustained);
  const bool apart = !EVENTS & !lub::contact_possible(gap, g.u_n, dt);
  // The spring acts: in sustained contact and touched (EVENTS: in overlap).
  out.stick = EVENTS ? gap < 0.0 : sustained & (touched != 0.0);
  // Whether the lane is done here, as doubles (a pair of immovable atoms, m_e = 0, is not: the
  // general loop drops it); m_e > 0 in a bool mask stops GCC 12 with inverse masses. A contact
  // that stuck throughout and whose overlap ended within the last step (touched 1, apart now, in
  // overlap a step ago) is the general loop's: its spring's release (tangential_release_force).
  const bool released = EVENTS & lub::overlap_just_ended(gap, g.u_n, dt) & (touched == 1.0);
  out.on = ((EVENTS ? resolved & !released : out.stick | apart) & (g.r > 0.0) ? 1.0 : 0.0) * (g.m_e > 0.0 ? 1.0 : 0.0);
  return out;
}

// Kept pairs with friction (lubricated/contact.h, contact_forces<true> over a step) of two kinds:
// in sustained contact (overlap now, a step ago and a step ahead, as contact_or_film decides) that
// touched at the last step: the normal contact and its saturated film (sustained_contact_force),
// the tangential spring with its rotation into the tangent plane and the Coulomb cap with the
// sliding reset (tangential_contact_force), the shear film (SHEAR, saturated); and apart over the
// step (no contact can act): the films alone (film_force_apart, the shear film as in
// film_shear_only) and the elongation forgotten. EVENTS: the kept pairs that loop leaves (a
// contact that starts or ends, one new since the last step) of a model without an entry loss,
// their normal force by lub::contact_event_force (done where it resolves them), the spring where
// in overlap from the part of the last step spent there (first_contact_fraction unless touched),
// the elongation forgotten elsewhere. Every branch of the scalar kernel a select here
// (-fno-trapping-math: a lane's unused division may be 0/0); 0/1 multipliers, not bool masks,
// where GCC 12 would not if-convert.
template <bool WET, bool GRID, bool SHEAR, bool INVERSE, bool EVENTS> __attribute__((always_inline)) inline void
friction_contact_loop(const Atoms &atoms, const lubricated::ContactModel &model, const int *__restrict pair_i,
                      const int *__restrict pair_j, const double *__restrict touched, const double *__restrict delta_x,
                      const double *__restrict delta_y, const double *__restrict delta_z, int n,
                      double *__restrict film_force, double *__restrict capacity, double *__restrict energy,
                      double *__restrict force_x, double *__restrict force_y, double *__restrict force_z,
                      double *__restrict torque_x, double *__restrict torque_y, double *__restrict torque_z,
                      double *__restrict shear_x, double *__restrict shear_y, double *__restrict shear_z,
                      double *__restrict slip_sq, double *__restrict tangential_mass, double *__restrict new_x,
                      double *__restrict new_y, double *__restrict new_z, double *__restrict new_touched,
                      double *__restrict done)
{
  namespace lub = lubricated;
  const Atoms local = atoms;
  const lub::NormalModel normal = model.normal;
  const lub::TangentialModel tm = model.tangential;
  for (int c = 0; c < n; c++) {
    const int i = pair_i[c], j = pair_j[c];
    const lub::PairGeometry g = lub::pair_geometry<INVERSE>(local, i, j);
    const double gap = g.r - g.radsum;
    const FrictionNormal state = friction_normal<WET, GRID, EVENTS>(normal, g, touched[c]);
    const double on = state.on, in_contact = state.stick ? on : 0.0;
    const bool ok = on != 0.0;
    const double radi = local.radius[i], radj = local.radius[j];
    const lub::Vec3 nv = lub::pair_normal(g);
    const lub::Vec3 s = lub::pair_slip(local, i, j, radi, radj, nv);
    const double m_t = lub::tangential_mass_ratio * g.m_e;
    // The part of the last step in overlap: all of it unless the contact is new (EVENTS).
    const double fraction = EVENTS & (touched[c] == 0.0) ? lub::first_contact_fraction(gap, g.u_n, tm.dt) : 1.0;
    lub::Vec3 delta{delta_x[c], delta_y[c], delta_z[c]};
    bool slid;
    const lub::Vec3 spring = lub::tangential_contact_force(tm, delta, nv, s, m_t, state.fn.contact, fraction, &slid);
    // Apart: no spring. EVENTS: selects (a lane it leaves may hold a NaN, from m_e = 0); the other
    // loop keeps its products (selects there stop GCC 12 vectorising one of its forms).
    const bool spring_on = in_contact != 0.0;
    lub::Vec3 f = EVENTS ? lub::Vec3{spring_on ? spring.x : 0.0, spring_on ? spring.y : 0.0, spring_on ? spring.z : 0.0}
                         : lub::scaled(spring, in_contact);
    lub::Vec3 h;
    if (SHEAR) {
      // Between eps_2 and eps_al (saturated in overlap): shear_log is the saturated film's there.
      const lub::Lubrication &film_law = normal.lubrication;
      const double eps_al = film_law.activation_inline_eps<GRID>(g.film);
      const double in_film = lub::in_shear_film(gap * g.film.inverse, eps_al, film_law.eps_release) ? on : 0.0;
      const double damping =
          lub::shear_film_damping<true>(tm, in_film, radi * radj / g.radsum, state.shear_log, ok ? m_t : 1.0);
      h = {-damping * s.x, -damping * s.y, -damping * s.z};
      f = lub::plus(f, h);
    }
    const double normal_total = state.stick | EVENTS ? state.fn.total() : state.film_apart;
    const double film_total = state.stick | EVENTS ? state.fn.lubrication : state.film_apart;
    const double fpair = EVENTS ? (ok ? normal_total * g.rinv : 0.0) : on * normal_total * g.rinv;
    film_force[c] = EVENTS ? (ok ? film_total : 0.0) : on * film_total;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = EVENTS ? (spring_on ? state.fn.energy : 0.0) : in_contact * state.fn.energy;
    force_x[c] = g.delx * fpair + f.x, force_y[c] = g.dely * fpair + f.y, force_z[c] = g.delz * fpair + f.z;
    // -n x F: the torque on i per unit of R_i (on j per unit of R_j).
    torque_x[c] = -(nv.y * f.z - nv.z * f.y), torque_y[c] = -(nv.z * f.x - nv.x * f.z),
    torque_z[c] = -(nv.x * f.y - nv.y * f.x);
    shear_x[c] = h.x, shear_y[c] = h.y, shear_z[c] = h.z;
    slip_sq[c] = s.x * s.x + s.y * s.y + s.z * s.z;
    tangential_mass[c] = ok ? m_t : 1.0;
    // Apart: a touching contact's elongation forgotten; else (not done) as it was.
    // (on is 0 or 1: a product, as bool masks here stop GCC 12 vectorising.)
    const double kept = 1.0 - on * (touched[c] != 0.0 ? 1.0 : 0.0);
    new_x[c] = spring_on ? delta.x : kept * delta_x[c];
    new_y[c] = spring_on ? delta.y : kept * delta_y[c];
    new_z[c] = spring_on ? delta.z : kept * delta_z[c];
    // The history's flag (lubricated::history_flag): 1 stuck throughout, 2 slid at some step.
    new_touched[c] = ok ? in_contact * (slid | (touched[c] == 2.0) ? 2.0 : 1.0) : touched[c];
    done[c] = on;
  }
}

}    // namespace vector_pairs
}    // namespace LAMMPS_NS

#endif
