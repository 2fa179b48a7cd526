// What the vectorised pair loops of both engines read of a pair (the LAMMPS pair style's
// vector_pairs.cpp, LIGGGHTS's close_pairs.cpp): the atoms' arrays and, per pair, the
// separation, normal velocity, radii and reduced mass, and the slip of the surfaces. Engine-free
// and without branches, for loops the compiler vectorises (gathers of the atoms' data).
#pragma once

#include "normal_model.h"
#include "tangential.h"

#include <cmath>

namespace lubricated {

// Per-atom data: x and v 3 per atom, contiguous (the engines' x[0], v[0]). inverse_mass: the
// inverse contact masses where a run has immovable atoms or rigid bodies, else nullptr (m_e from
// rmass). omega (3 per atom): for the slip only (friction, shear film).
struct PairAtoms {
  const double *x, *v, *radius, *rmass, *inverse_mass;
  const double *omega = nullptr;
};

// Separation (i minus j), its length and inverse, the normal velocity u_n, the radii's sum, the
// film's radius and the reduced mass.
struct PairGeometry {
  double delx, dely, delz, r, rinv, u_n, radsum, m_e;
  FilmRadius film;
};

// INVERSE: m_e from the inverse contact masses (0 for two immovable atoms, whose forces are then 0).
template <bool INVERSE>
__attribute__((always_inline)) inline PairGeometry pair_geometry(const PairAtoms &atoms, int i, int j)
{
  const double *__restrict x = atoms.x;
  const double *__restrict v = atoms.v;
  PairGeometry g;
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
  g.film = film_radius_pair(radi, radj);
  if (INVERSE)
    g.m_e = reduced_mass_of_inverses(atoms.inverse_mass[i], atoms.inverse_mass[j]);
  else
    g.m_e = atoms.rmass[i] * atoms.rmass[j] / (atoms.rmass[i] + atoms.rmass[j]);
  return g;
}

// The unit normal n from j to i.
__attribute__((always_inline)) inline Vec3 pair_normal(const PairGeometry &g)
{
  return {g.delx * g.rinv, g.dely * g.rinv, g.delz * g.rinv};
}

// The slip of the surfaces of pair (i, j) (surface_slip), radii radius_i and radius_j.
__attribute__((always_inline)) inline Vec3 pair_slip(const PairAtoms &atoms, int i, int j, double radius_i,
                                                     double radius_j, const Vec3 &n)
{
  const double *__restrict v = atoms.v;
  const double *__restrict omega = atoms.omega;
  const Vec3 omega_i{omega[3 * i], omega[3 * i + 1], omega[3 * i + 2]};
  const Vec3 omega_j{omega[3 * j], omega[3 * j + 1], omega[3 * j + 2]};
  const Vec3 lever = contact_lever(omega_i, radius_i, omega_j, radius_j);
  const Vec3 dv{v[3 * i] - v[3 * j], v[3 * i + 1] - v[3 * j + 1], v[3 * i + 2] - v[3 * j + 2]};
  return surface_slip(dv, lever, n);
}

}    // namespace lubricated
