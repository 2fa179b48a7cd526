/* ----------------------------------------------------------------------
   Vectorised loops of pair style lubricated/springdashpot (see vector_pairs.h)
------------------------------------------------------------------------- */

#include "vector_pairs.h"

#include <cmath>

namespace lub = lubricated;

// x86-64-v3 (AVX2) and v4 (AVX-512) have the gathers the loops need; elsewhere they run scalar.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define VECTOR_PAIRS_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define VECTOR_PAIRS_CLONES
#endif

namespace LAMMPS_NS {
namespace vector_pairs {

// What every pair needs: separation, normal velocity, radii and reduced mass (INVERSE:
// from the inverse contact masses; 0 for two immovable atoms, whose forces are then 0).
struct Geometry {
  double delx, dely, delz, r, rinv, u_n, radsum, m_e;
  lub::FilmRadius film;
};

template <bool INVERSE> __attribute__((always_inline)) static inline Geometry geometry(const Atoms &atoms, int i, int j)
{
  const double *__restrict x = atoms.x;
  const double *__restrict v = atoms.v;
  Geometry g;
  g.delx = x[3 * i] - x[3 * j];
  g.dely = x[3 * i + 1] - x[3 * j + 1];
  g.delz = x[3 * i + 2] - x[3 * j + 2];
  const double dvx = v[3 * i] - v[3 * j];
  const double dvy = v[3 * i + 1] - v[3 * j + 1];
  const double dvz = v[3 * i + 2] - v[3 * j + 2];
  g.r = std::sqrt(g.delx * g.delx + g.dely * g.dely + g.delz * g.delz);
  g.rinv = 1.0 / g.r;
  g.u_n = (dvx * g.delx + dvy * g.dely + dvz * g.delz) * g.rinv;
  const double radi = atoms.radius[i], radj = atoms.radius[j];
  g.radsum = radi + radj;
  g.film = lub::film_radius_pair(radi, radj);
  if (INVERSE)
    g.m_e = lub::reduced_mass_of_inverses(atoms.inverse_mass[i], atoms.inverse_mass[j]);
  else
    g.m_e = atoms.rmass[i] * atoms.rmass[j] / (atoms.rmass[i] + atoms.rmass[j]);
  return g;
}

template <bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
film_only_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
               const int *__restrict pair_j, int n, double *__restrict force_x, double *__restrict force_y,
               double *__restrict force_z, double *__restrict film_force, double *__restrict capacity)
{
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  for (int c = 0; c < n; c++) {
    const Geometry g = geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const double film =
        lub::film_force_apart<GRID>(model.lubrication, g.r - g.radsum, g.film, g.m_e, g.u_n, dt, inv_dt);
    const double fpair = g.rinv * film;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    film_force[c] = film;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
  }
}

template <bool WET, bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
contact_or_film_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
                     const int *__restrict pair_j, int n, double *__restrict force_x, double *__restrict force_y,
                     double *__restrict force_z, double *__restrict film_force, double *__restrict capacity,
                     double *__restrict energy, double *__restrict done)
{
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  for (int c = 0; c < n; c++) {
    const Geometry g = geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const double gap = g.r - g.radsum;
    // Apart over the step (no contact can act): the film alone, as in film_only. Wet, its
    // lambda(eps_al) serves the sustained contact's saturated film too (one logarithm fewer).
    double shear_log, lambda_al = 0.0;
    const double film = WET ? lub::film_force_apart<GRID>(model.lubrication, gap, g.film, g.m_e, g.u_n, dt, inv_dt,
                                                          shear_log, lambda_al)
                            : 0.0;
    bool sustained;
    const lub::NormalForce contact =
        WET ? lub::sustained_contact_force(model, gap, g.film, g.m_e, g.u_n, lambda_al, sustained)
            : lub::sustained_contact_force<GRID>(model, gap, g.film, g.m_e, g.u_n, sustained);
    const bool apart = !lub::contact_possible(gap, g.u_n, dt);
    const bool known = (sustained | apart) & (g.r > 0.0);
    const double fpair = known ? (sustained ? contact.total() : film) * g.rinv : 0.0;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    // The shares themselves are divided out by the caller: with that division in it, GCC 12
    // no longer if-converts (and vectorises) this loop.
    film_force[c] = WET & known ? (sustained ? contact.lubrication : film) : 0.0;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = known & sustained ? contact.energy : 0.0;
    // 2: leaving the overlap within the coming step (contact_exits; never known: in overlap,
    // not sustained). Doubles: with an int output GCC 12 does not vectorise this loop.
    const bool exits = lub::leaves_overlap(model.step, gap, gap - g.u_n * dt) & (g.r > 0.0);
    done[c] = (known ? 1.0 : 0.0) + (exits ? 2.0 : 0.0);
  }
}

// Kept pairs that leave the overlap within the coming step (lub::leaves_overlap): the exit's
// force, the saturated film and the spring's energy; as contact_or_film's outputs.
template <bool WET, bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
contact_exit_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
                  const int *__restrict pair_j, int n, double *__restrict force_x, double *__restrict force_y,
                  double *__restrict force_z, double *__restrict film_force, double *__restrict capacity,
                  double *__restrict energy)
{
  for (int c = 0; c < n; c++) {
    const Geometry g = geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const lub::NormalForce f = lub::overlap_exit_force<GRID>(model, g.r - g.radsum, g.film, g.m_e, g.u_n);
    const double fpair = f.total() * g.rinv;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    film_force[c] = WET ? f.lubrication : 0.0;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = f.energy;
  }
}

// Kept pairs where a contact starts or ends (contact_or_film's done = 0) of a model without an
// entry loss: done[c] = 1 with contact_or_film's outputs where lub::contact_event_force resolves
// pair c (or neither atom moves: no force), else 0 for the general loop (outputs 0).
template <bool WET, bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
contact_event_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
                   const int *__restrict pair_j, int n, double *__restrict force_x, double *__restrict force_y,
                   double *__restrict force_z, double *__restrict film_force, double *__restrict capacity,
                   double *__restrict energy, double *__restrict done)
{
  // Local copies (as film_shear_only_loop): no store can alias them, so their loads (the guess
  // tables' pointers among them) leave the loop.
  const Atoms local = atoms;
  const lub::NormalModel local_model = model;
  for (int c = 0; c < n; c++) {
    const Geometry g = geometry<INVERSE>(local, pair_i[c], pair_j[c]);
    bool resolved;
    const lub::NormalForce f =
        lub::contact_event_force<WET, GRID>(local_model, g.r - g.radsum, g.film, g.m_e, g.u_n, resolved);
    // Whether the pair moves as a double (a bool of m_e > 0 stops GCC 12 vectorising the loop
    // with inverse masses); a pair neither of whose atoms moves is done without a force.
    const double moving = g.m_e > 0.0 ? 1.0 : 0.0;
    const bool known = resolved & (moving != 0.0) & (g.r > 0.0);
    const double fpair = known ? f.total() * g.rinv : 0.0;
    force_x[c] = g.delx * fpair, force_y[c] = g.dely * fpair, force_z[c] = g.delz * fpair;
    film_force[c] = WET & known ? f.lubrication : 0.0;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = known ? f.energy : 0.0;
    done[c] = g.r > 0.0 ? (resolved ? 1.0 : 1.0 - moving) : 0.0;
  }
}

// RECORDS: whether the film budget's inputs are written (film, capacity, shear, slip_sq and
// tangential_mass); the force and torque always.
template <bool GRID, bool INVERSE, bool RECORDS> __attribute__((always_inline)) static inline void
film_shear_only_loop(const Atoms &atoms, const lub::ContactModel &model, const int *__restrict pair_i,
                     const int *__restrict pair_j, int n, double *__restrict film_force, double *__restrict capacity,
                     double *__restrict force_x, double *__restrict force_y, double *__restrict force_z,
                     double *__restrict shear_x, double *__restrict shear_y, double *__restrict shear_z,
                     double *__restrict torque_x, double *__restrict torque_y, double *__restrict torque_z,
                     double *__restrict slip_sq, double *__restrict tangential_mass)
{
  // The outputs as restrict parameters: restrict pointers read from a struct do not convince
  // GCC 12 that the stores do not alias (the loop then stays scalar).
  // A local copy of the atoms' pointers and of the model: no store can alias them, so their
  // loads leave the loop.
  const Atoms local = atoms;
  const lub::Lubrication film_law = model.normal.lubrication;
  const lub::TangentialModel shear_law = model.tangential;
  const double dt = model.normal.step.dt, inv_dt = model.normal.step.inv_dt;
  const double *__restrict omega = local.omega;
  for (int c = 0; c < n; c++) {
    const int i = pair_i[c], j = pair_j[c];
    const Geometry g = geometry<INVERSE>(local, i, j);
    const double gap = g.r - g.radsum;
    double shear_log;    // the shear film's logarithm, from the normal film's
    const double film = lub::film_force_apart<GRID>(film_law, gap, g.film, g.m_e, g.u_n, dt, inv_dt, shear_log);
    const double normal = g.rinv * film;
    if (RECORDS) film_force[c] = film, capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    // The slip of the surfaces (lubricated/tangential.h) and the shear film on it, in plain
    // doubles (a helper left out of line in this large loop body would stop the vectoriser).
    const double radi = local.radius[i], radj = local.radius[j];
    const double nx = g.delx * g.rinv, ny = g.dely * g.rinv, nz = g.delz * g.rinv;
    const double *__restrict v = local.v;
    const double lx = radi * omega[3 * i] + radj * omega[3 * j];
    const double ly = radi * omega[3 * i + 1] + radj * omega[3 * j + 1];
    const double lz = radi * omega[3 * i + 2] + radj * omega[3 * j + 2];
    // (v_i - v_j) - lever x n, then its part normal to n.
    const double ax = v[3 * i] - v[3 * j] - (ly * nz - lz * ny);
    const double ay = v[3 * i + 1] - v[3 * j + 1] - (lz * nx - lx * nz);
    const double az = v[3 * i + 2] - v[3 * j + 2] - (lx * ny - ly * nx);
    const double along = ax * nx + ay * ny + az * nz;
    const double sx = ax - nx * along, sy = ay - ny * along, sz = az - nz * along;
    const double m_t = lub::tangential_mass_ratio * g.m_e;
    const double eps_al = film_law.activation_inline<GRID>(g.film).eps;
    const double damping = lub::shear_film_damping_of_log(shear_law, gap * g.film.inverse, eps_al, film_law.eps_release,
                                                          shear_log, radi * radj / g.radsum, m_t);
    const double fx = -damping * sx, fy = -damping * sy, fz = -damping * sz;
    if (RECORDS) shear_x[c] = fx, shear_y[c] = fy, shear_z[c] = fz;
    force_x[c] = g.delx * normal + fx, force_y[c] = g.dely * normal + fy, force_z[c] = g.delz * normal + fz;
    // -n x F: the torque on i per unit of R_i (on j per unit of R_j).
    torque_x[c] = -(ny * fz - nz * fy), torque_y[c] = -(nz * fx - nx * fz), torque_z[c] = -(nx * fy - ny * fx);
    if (RECORDS) slip_sq[c] = sx * sx + sy * sy + sz * sz, tangential_mass[c] = m_t;
  }
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
// (-fno-trapping-math: a lane's unused division may be 0/0), in the scalar kernel's order of
// operations; 0/1 multipliers, not bool masks, where GCC 12 would not if-convert.
template <bool WET, bool GRID, bool SHEAR, bool INVERSE, bool EVENTS> __attribute__((always_inline)) static inline void
friction_contact_loop(const Atoms &atoms, const lub::ContactModel &model, const int *__restrict pair_i,
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
  const Atoms local = atoms;
  const lub::NormalModel normal = model.normal;
  const lub::TangentialModel tm = model.tangential;
  const double *__restrict omega = local.omega;
  const double *__restrict v = local.v;
  const double dt = normal.step.dt, inv_dt = normal.step.inv_dt;
  const double eps_1 = normal.lubrication.eps_saturation, eps_2 = normal.lubrication.eps_release;
  const double dx_al = lub::Lubrication::grid_activation * normal.lubrication.grid_spacing;
  for (int c = 0; c < n; c++) {
    const int i = pair_i[c], j = pair_j[c];
    const Geometry g = geometry<INVERSE>(local, i, j);
    const double gap = g.r - g.radsum;
    bool sustained = false, resolved = true;
    double shear_log = 0.0;    // the shear film's logarithm, from the normal film's (WET)
    double lambda_al = 0.0;    // lambda(eps_al), from the film apart's (WET, not EVENTS)
    const double film_apart = WET & !EVENTS ? lub::film_force_apart<GRID>(normal.lubrication, gap, g.film, g.m_e, g.u_n,
                                                                          dt, inv_dt, shear_log, lambda_al)
                                            : 0.0;
    // Dry: the film terms are 0 (six_pi_mu = 0).
    const lub::NormalForce fn =
        EVENTS ? lub::contact_event_force<WET, GRID>(normal, gap, g.film, g.m_e, g.u_n, resolved, shear_log)
        : WET  ? lub::sustained_contact_force(normal, gap, g.film, g.m_e, g.u_n, lambda_al, sustained)
               : lub::sustained_contact_force<GRID>(normal, gap, g.film, g.m_e, g.u_n, sustained);
    const bool apart = !EVENTS & !lub::contact_possible(gap, g.u_n, dt);
    // The spring acts: in sustained contact and touched (EVENTS: in overlap).
    const bool stick = EVENTS ? gap < 0.0 : sustained & (touched[c] != 0.0);
    // Whether the lane is done here, as doubles (a pair of immovable atoms, m_e = 0, is not: the
    // general loop drops it); m_e > 0 in a bool mask stops GCC 12 with inverse masses.
    const double on = ((EVENTS ? resolved : stick | apart) & (g.r > 0.0) ? 1.0 : 0.0) * (g.m_e > 0.0 ? 1.0 : 0.0);
    const double in_contact = stick ? on : 0.0;
    const bool ok = on != 0.0;
    // The slip (lubricated/tangential.h): (v_i - v_j) - (R_i w_i + R_j w_j) x n, its normal part removed.
    const double radi = local.radius[i], radj = local.radius[j];
    const double nx = g.delx * g.rinv, ny = g.dely * g.rinv, nz = g.delz * g.rinv;
    const double lx = radi * omega[3 * i] + radj * omega[3 * j];
    const double ly = radi * omega[3 * i + 1] + radj * omega[3 * j + 1];
    const double lz = radi * omega[3 * i + 2] + radj * omega[3 * j + 2];
    const double ax = v[3 * i] - v[3 * j] - (ly * nz - lz * ny);
    const double ay = v[3 * i + 1] - v[3 * j + 1] - (lz * nx - lx * nz);
    const double az = v[3 * i + 2] - v[3 * j + 2] - (lx * ny - ly * nx);
    const double along = ax * nx + ay * ny + az * nz;
    const double sx = ax - nx * along, sy = ay - ny * along, sz = az - nz * along;
    const double m_t = lub::tangential_mass_ratio * g.m_e;
    // The elongation kept in the tangent plane with its length (series or square root).
    double dx = delta_x[c], dy = delta_y[c], dz = delta_z[c];
    const double normal_part = dx * nx + dy * ny + dz * nz;
    const double length_sq = dx * dx + dy * dy + dz * dz;
    dx = dx - nx * normal_part, dy = dy - ny * normal_part, dz = dz - nz * normal_part;
    const double x = normal_part != 0.0 ? normal_part * normal_part / length_sq : 0.0;
    const double stretch = x < 1e-4 ? 1.0 + x * (0.5 + 0.375 * x) : x < 1.0 ? std::sqrt(1.0 / (1.0 - x)) : 1.0;
    // The part of the last step in overlap: all of it unless the contact is new (EVENTS).
    const double fraction = EVENTS & (touched[c] == 0.0) ? lub::first_contact_fraction(gap, g.u_n, tm.dt) : 1.0;
    const double step = fraction * tm.dt;
    dx = dx * stretch + sx * step, dy = dy * stretch + sy * step, dz = dz * stretch + sz * step;
    double fx = (dx * tm.stiffness_step + sx * tm.damping_step) * -m_t;
    double fy = (dy * tm.stiffness_step + sy * tm.damping_step) * -m_t;
    double fz = (dz * tm.stiffness_step + sz * tm.damping_step) * -m_t;
    // Coulomb: beyond mu |F_n| the contact slides and the spring holds what the capped force implies.
    const double limit = tm.friction * std::fabs(fn.contact);
    const double f2 = fx * fx + fy * fy + fz * fz;
    const bool slides = f2 > limit * limit;
    const double cap = slides ? limit / std::sqrt(f2) : 1.0;
    fx *= cap, fy *= cap, fz *= cap;
    const double inv_m_t = 1.0 / m_t, inv_k = -1.0 / tm.stiffness_step;
    dx = slides ? (fx * inv_m_t + sx * tm.damping_step) * inv_k : dx;
    dy = slides ? (fy * inv_m_t + sy * tm.damping_step) * inv_k : dy;
    dz = slides ? (fz * inv_m_t + sz * tm.damping_step) * inv_k : dz;
    // Apart: no spring. EVENTS: selects (a lane it leaves may hold a NaN, from m_e = 0); the other
    // loop keeps its products (selects there stop GCC 12 vectorising one of its forms).
    const bool spring = in_contact != 0.0;
    fx = EVENTS ? (spring ? fx : 0.0) : fx * in_contact;
    fy = EVENTS ? (spring ? fy : 0.0) : fy * in_contact;
    fz = EVENTS ? (spring ? fz : 0.0) : fz * in_contact;
    double hx = 0.0, hy = 0.0, hz = 0.0;
    if (SHEAR) {
      // 2 pi mu R_e ln(eps_al / max(eps, eps_1)) between eps_2 and eps_al (saturated in overlap).
      const double eps = gap * g.film.inverse;
      const double eps_al = GRID ? std::max(dx_al * g.film.inverse, eps_1) : normal.lubrication.eps_activation;
      const double in_film = (eps < eps_al) & (eps > eps_2) ? on : 0.0;
      const double mass = ok ? m_t : 1.0;
      const double rate = in_film * tm.two_pi_mu * (radi * radj / g.radsum) * shear_log * tm.dt / mass;
      const double damping = lub::one_minus_exp_neg_inline(rate) * mass / tm.dt;
      hx = -damping * sx, hy = -damping * sy, hz = -damping * sz;
      fx += hx, fy += hy, fz += hz;
    }
    const double normal_total = stick | EVENTS ? fn.total() : film_apart;
    const double film_total = stick | EVENTS ? fn.lubrication : film_apart;
    const double normal = EVENTS ? (ok ? normal_total * g.rinv : 0.0) : on * normal_total * g.rinv;
    film_force[c] = EVENTS ? (ok ? film_total : 0.0) : on * film_total;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = EVENTS ? (spring ? fn.energy : 0.0) : in_contact * fn.energy;
    force_x[c] = g.delx * normal + fx, force_y[c] = g.dely * normal + fy, force_z[c] = g.delz * normal + fz;
    // -n x F: the torque on i per unit of R_i (on j per unit of R_j).
    torque_x[c] = -(ny * fz - nz * fy), torque_y[c] = -(nz * fx - nx * fz), torque_z[c] = -(nx * fy - ny * fx);
    shear_x[c] = hx, shear_y[c] = hy, shear_z[c] = hz;
    slip_sq[c] = sx * sx + sy * sy + sz * sz;
    tangential_mass[c] = ok ? m_t : 1.0;
    // Apart: a touching contact's elongation forgotten; else (not done) as it was.
    // (touched and on are 0 or 1: a product, as bool masks here stop GCC 12 vectorising.)
    const double kept = 1.0 - on * touched[c];
    new_x[c] = in_contact != 0.0 ? dx : kept * delta_x[c];
    new_y[c] = in_contact != 0.0 ? dy : kept * delta_y[c];
    new_z[c] = in_contact != 0.0 ? dz : kept * delta_z[c];
    new_touched[c] = ok ? in_contact : touched[c];
    done[c] = on;
  }
}

// Each entry point compiles its own loops (the plain ones exactly as without contact masses).
VECTOR_PAIRS_CLONES
void film_only(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
               const ForceOut &force, double *film, double *capacity)
{
  if (model.lubrication.grid_spacing > 0.0)
    film_only_loop<true, false>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity);
  else
    film_only_loop<false, false>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity);
}

VECTOR_PAIRS_CLONES
void film_only_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                          int n, const ForceOut &force, double *film, double *capacity)
{
  if (model.lubrication.grid_spacing > 0.0)
    film_only_loop<true, true>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity);
  else
    film_only_loop<false, true>(atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity);
}

// The loop LOOP<WET, GRID, INVERSE> for the model's film: dry, wet with a grid, wet without.
#define NORMAL_LOOP(LOOP, INVERSE, ...)                                                                                \
  do {                                                                                                                 \
    const bool wet = model.lubrication.active(), grid = model.lubrication.grid_spacing > 0.0;                          \
    if (!wet)                                                                                                          \
      LOOP<false, false, INVERSE>(__VA_ARGS__);                                                                        \
    else if (grid)                                                                                                     \
      LOOP<true, true, INVERSE>(__VA_ARGS__);                                                                          \
    else                                                                                                               \
      LOOP<true, false, INVERSE>(__VA_ARGS__);                                                                         \
  } while (false)

VECTOR_PAIRS_CLONES
void contact_or_film(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
                     const ForceOut &force, double *film, double *capacity, double *energy, double *done)
{
  NORMAL_LOOP(contact_or_film_loop, false, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

VECTOR_PAIRS_CLONES
void contact_or_film_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                                int n, const ForceOut &force, double *film, double *capacity, double *energy,
                                double *done)
{
  NORMAL_LOOP(contact_or_film_loop, true, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

VECTOR_PAIRS_CLONES
void contact_exits(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
                   const ForceOut &force, double *film, double *capacity, double *energy)
{
  NORMAL_LOOP(contact_exit_loop, false, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy);
}

VECTOR_PAIRS_CLONES
void contact_exits_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                              int n, const ForceOut &force, double *film, double *capacity, double *energy)
{
  NORMAL_LOOP(contact_exit_loop, true, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy);
}

VECTOR_PAIRS_CLONES
void contact_events(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
                    const ForceOut &force, double *film, double *capacity, double *energy, double *done)
{
  NORMAL_LOOP(contact_event_loop, false, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

VECTOR_PAIRS_CLONES
void contact_events_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                               int n, const ForceOut &force, double *film, double *capacity, double *energy,
                               double *done)
{
  NORMAL_LOOP(contact_event_loop, true, atoms, model, pair_i, pair_j, n, force.x, force.y, force.z, film, capacity,
              energy, done);
}

#undef NORMAL_LOOP

#define SHEAR_OUTPUTS(o)                                                                                               \
  o.force_x, o.force_y, o.force_z, o.shear_x, o.shear_y, o.shear_z, o.torque_x, o.torque_y, o.torque_z, o.slip_sq,     \
      o.tangential_mass

// film_shear_only_loop<GRID, INVERSE, RECORDS> for the model's film and the caller's records.
#define SHEAR_LOOP(INVERSE)                                                                                            \
  do {                                                                                                                 \
    const bool grid = model.normal.lubrication.grid_spacing > 0.0;                                                     \
    if (grid && records)                                                                                               \
      film_shear_only_loop<true, INVERSE, true>(atoms, model, pair_i, pair_j, n, film, capacity,                       \
                                                SHEAR_OUTPUTS(shear));                                                 \
    else if (grid)                                                                                                     \
      film_shear_only_loop<true, INVERSE, false>(atoms, model, pair_i, pair_j, n, film, capacity,                      \
                                                 SHEAR_OUTPUTS(shear));                                                \
    else if (records)                                                                                                  \
      film_shear_only_loop<false, INVERSE, true>(atoms, model, pair_i, pair_j, n, film, capacity,                      \
                                                 SHEAR_OUTPUTS(shear));                                                \
    else                                                                                                               \
      film_shear_only_loop<false, INVERSE, false>(atoms, model, pair_i, pair_j, n, film, capacity,                     \
                                                  SHEAR_OUTPUTS(shear));                                               \
  } while (false)

VECTOR_PAIRS_CLONES
void film_shear_only(const Atoms &atoms, const lub::ContactModel &model, const int *pair_i, const int *pair_j, int n,
                     double *film, double *capacity, const ShearOut &shear, bool records)
{
  SHEAR_LOOP(false);
}

VECTOR_PAIRS_CLONES
void film_shear_only_by_inverse(const Atoms &atoms, const lub::ContactModel &model, const int *pair_i,
                                const int *pair_j, int n, double *film, double *capacity, const ShearOut &shear,
                                bool records)
{
  SHEAR_LOOP(true);
}

#undef SHEAR_LOOP

#define CONTACT_ARGUMENTS(o)                                                                                           \
  o.film, o.capacity, o.energy, o.force_x, o.force_y, o.force_z, o.torque_x, o.torque_y, o.torque_z, o.shear_x,        \
      o.shear_y, o.shear_z, o.slip_sq, o.tangential_mass, o.new_x, o.new_y, o.new_z, o.new_touched, o.done

// One entry point per mass form; the model picks the loop (dry; wet with or without a grid and a
// shear film).
template <bool INVERSE, bool EVENTS> __attribute__((always_inline)) static inline void
friction_contacts_of(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                     const FrictionOut &out)
{
  const lub::Lubrication &film = model.normal.lubrication;
  const bool wet = film.active(), grid = film.grid_spacing > 0.0, shear = model.tangential.film_active();
#define FRICTION_LOOP(W, G, S)                                                                                         \
  friction_contact_loop<W, G, S, INVERSE, EVENTS>(atoms, model, in.pair_i, in.pair_j, in.touched, in.delta_x,          \
                                                  in.delta_y, in.delta_z, n, CONTACT_ARGUMENTS(out))
  if (!wet)
    FRICTION_LOOP(false, false, false);
  else if (grid && shear)
    FRICTION_LOOP(true, true, true);
  else if (grid)
    FRICTION_LOOP(true, true, false);
  else if (shear)
    FRICTION_LOOP(true, false, true);
  else
    FRICTION_LOOP(true, false, false);
#undef FRICTION_LOOP
}

VECTOR_PAIRS_CLONES
void friction_contacts(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                       const FrictionOut &out)
{
  friction_contacts_of<false, false>(atoms, model, in, n, out);
}

VECTOR_PAIRS_CLONES
void friction_contacts_by_inverse(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                                  const FrictionOut &out)
{
  friction_contacts_of<true, false>(atoms, model, in, n, out);
}

VECTOR_PAIRS_CLONES
void friction_events(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                     const FrictionOut &out)
{
  friction_contacts_of<false, true>(atoms, model, in, n, out);
}

VECTOR_PAIRS_CLONES
void friction_events_by_inverse(const Atoms &atoms, const lub::ContactModel &model, const FrictionIn &in, int n,
                                const FrictionOut &out)
{
  friction_contacts_of<true, true>(atoms, model, in, n, out);
}

}    // namespace vector_pairs
}    // namespace LAMMPS_NS
