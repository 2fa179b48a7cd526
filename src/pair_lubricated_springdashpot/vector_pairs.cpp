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
               const int *__restrict pair_j, int n, double *__restrict fpair, double *__restrict film_force,
               double *__restrict capacity)
{
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  for (int c = 0; c < n; c++) {
    const Geometry g = geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const double film =
        lub::film_force_apart<GRID>(model.lubrication, g.r - g.radsum, g.film, g.m_e, g.u_n, dt, inv_dt);
    fpair[c] = g.rinv * film;
    film_force[c] = film;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
  }
}

template <bool WET, bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
contact_or_film_loop(const Atoms &atoms, const lub::NormalModel &model, const int *__restrict pair_i,
                     const int *__restrict pair_j, int n, double *__restrict fpair, double *__restrict film_force,
                     double *__restrict capacity, double *__restrict energy, int *__restrict done)
{
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  for (int c = 0; c < n; c++) {
    const Geometry g = geometry<INVERSE>(atoms, pair_i[c], pair_j[c]);
    const double gap = g.r - g.radsum;
    bool sustained;
    const lub::NormalForce contact = lub::sustained_contact_force<GRID>(model, gap, g.film, g.m_e, g.u_n, sustained);
    // Apart over the step (no contact can act): the film alone, as in film_only.
    const bool apart = !lub::contact_possible(gap, g.u_n, dt);
    const double film =
        WET ? lub::film_force_apart<GRID>(model.lubrication, gap, g.film, g.m_e, g.u_n, dt, inv_dt) : 0.0;
    const bool known = (sustained | apart) & (g.r > 0.0);
    fpair[c] = known ? (sustained ? contact.total() : film) * g.rinv : 0.0;
    // The shares themselves are divided out by the caller: with that division in it, GCC 12
    // no longer if-converts (and vectorises) this loop.
    film_force[c] = WET & known ? (sustained ? contact.lubrication : film) : 0.0;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
    energy[c] = known & sustained ? contact.energy : 0.0;
    done[c] = known;
  }
}

template <bool GRID, bool INVERSE> __attribute__((always_inline)) static inline void
film_shear_only_loop(const Atoms &atoms, const lub::ContactModel &model, const int *__restrict pair_i,
                     const int *__restrict pair_j, int n, double *__restrict fpair, double *__restrict film_force,
                     double *__restrict capacity, double *__restrict shear_x, double *__restrict shear_y,
                     double *__restrict shear_z, double *__restrict torque_x, double *__restrict torque_y,
                     double *__restrict torque_z, double *__restrict slip_sq, double *__restrict tangential_mass)
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
    const double film = lub::film_force_apart<GRID>(film_law, gap, g.film, g.m_e, g.u_n, dt, inv_dt);
    fpair[c] = g.rinv * film;
    film_force[c] = film;
    capacity[c] = lub::film_capacity(g.m_e, g.u_n);
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
    const double damping =
        lub::shear_film_damping_apart(shear_law, gap * g.film.inverse, eps_al, film_law.eps_saturation,
                                      film_law.eps_release, radi * radj / g.radsum, m_t);
    const double fx = -damping * sx, fy = -damping * sy, fz = -damping * sz;
    shear_x[c] = fx, shear_y[c] = fy, shear_z[c] = fz;
    // -n x F: the torque on i per unit of R_i (on j per unit of R_j).
    torque_x[c] = -(ny * fz - nz * fy), torque_y[c] = -(nz * fx - nx * fz), torque_z[c] = -(nx * fy - ny * fx);
    slip_sq[c] = sx * sx + sy * sy + sz * sz;
    tangential_mass[c] = m_t;
  }
}

// Each entry point compiles its own loops (the plain ones exactly as without contact masses).
VECTOR_PAIRS_CLONES
void film_only(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
               double *fpair, double *film, double *capacity)
{
  if (model.lubrication.grid_spacing > 0.0)
    film_only_loop<true, false>(atoms, model, pair_i, pair_j, n, fpair, film, capacity);
  else
    film_only_loop<false, false>(atoms, model, pair_i, pair_j, n, fpair, film, capacity);
}

VECTOR_PAIRS_CLONES
void film_only_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                          int n, double *fpair, double *film, double *capacity)
{
  if (model.lubrication.grid_spacing > 0.0)
    film_only_loop<true, true>(atoms, model, pair_i, pair_j, n, fpair, film, capacity);
  else
    film_only_loop<false, true>(atoms, model, pair_i, pair_j, n, fpair, film, capacity);
}

VECTOR_PAIRS_CLONES
void contact_or_film(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n,
                     double *fpair, double *film, double *capacity, double *energy, int *done)
{
  const bool wet = model.lubrication.active(), grid = model.lubrication.grid_spacing > 0.0;
  if (!wet)
    contact_or_film_loop<false, false, false>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
  else if (grid)
    contact_or_film_loop<true, true, false>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
  else
    contact_or_film_loop<true, false, false>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
}

VECTOR_PAIRS_CLONES
void contact_or_film_by_inverse(const Atoms &atoms, const lub::NormalModel &model, const int *pair_i, const int *pair_j,
                                int n, double *fpair, double *film, double *capacity, double *energy, int *done)
{
  const bool wet = model.lubrication.active(), grid = model.lubrication.grid_spacing > 0.0;
  if (!wet)
    contact_or_film_loop<false, false, true>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
  else if (grid)
    contact_or_film_loop<true, true, true>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
  else
    contact_or_film_loop<true, false, true>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
}

#define SHEAR_OUTPUTS(o)                                                                                               \
  o.shear_x, o.shear_y, o.shear_z, o.torque_x, o.torque_y, o.torque_z, o.slip_sq, o.tangential_mass

VECTOR_PAIRS_CLONES
void film_shear_only(const Atoms &atoms, const lub::ContactModel &model, const int *pair_i, const int *pair_j, int n,
                     double *fpair, double *film, double *capacity, const ShearOut &shear)
{
  if (model.normal.lubrication.grid_spacing > 0.0)
    film_shear_only_loop<true, false>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, SHEAR_OUTPUTS(shear));
  else
    film_shear_only_loop<false, false>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, SHEAR_OUTPUTS(shear));
}

VECTOR_PAIRS_CLONES
void film_shear_only_by_inverse(const Atoms &atoms, const lub::ContactModel &model, const int *pair_i,
                                const int *pair_j, int n, double *fpair, double *film, double *capacity,
                                const ShearOut &shear)
{
  if (model.normal.lubrication.grid_spacing > 0.0)
    film_shear_only_loop<true, true>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, SHEAR_OUTPUTS(shear));
  else
    film_shear_only_loop<false, true>(atoms, model, pair_i, pair_j, n, fpair, film, capacity, SHEAR_OUTPUTS(shear));
}

}    // namespace vector_pairs
}    // namespace LAMMPS_NS
