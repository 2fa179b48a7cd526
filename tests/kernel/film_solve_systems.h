// Test systems for the coupled film solve (lubricated/film_solve.h): random spheres and films,
// and the backward-Euler step (M + dt R) w' = M w + dt (F + f_wall) solved densely, built here
// independently of the kernel (each film's relative-velocity rows B_k, R = sum c B_k^T B_k).
#pragma once

#include "lubricated/film_solve.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

namespace film_solve_test {

using namespace lubricated;

struct System {
  std::vector<double> inverse_mass, inverse_inertia, radius, velocity, force;
  std::vector<double> drag, rotational_drag;    // empty: none
  std::vector<FilmLink> links;
  int n() const { return int(radius.size()); }
  FilmAtoms atoms() const
  {
    FilmAtoms a;
    a.owned = a.total = n();
    a.inverse_mass = inverse_mass.data();
    a.inverse_inertia = inverse_inertia.data();
    a.radius = radius.data();
    if (!drag.empty()) a.drag = drag.data(), a.rotational_drag = rotational_drag.data();
    return a;
  }
};

inline Vec3 random_unit(std::mt19937 &rng)
{
  std::normal_distribution<double> g;
  Vec3 v{g(rng), g(rng), g(rng)};
  return scaled(v, 1.0 / std::sqrt(dot(v, v)));
}

// Random spheres (radii 0.5-1.5, density 1, some immovable), films between random pairs and
// walls with shares c dt / m_e up to max_share, random velocities and forces.
inline System random_system(unsigned seed, int n, int n_pairs, int n_walls, double dt, double max_share, bool forces)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  System s;
  for (int i = 0; i < n; i++) {
    const double r = 0.5 + u(rng), m = 4.18879 * r * r * r;
    const bool immovable = u(rng) < 0.1;
    s.radius.push_back(r);
    s.inverse_mass.push_back(immovable ? 0.0 : 1.0 / m);
    s.inverse_inertia.push_back(immovable ? 0.0 : 1.0 / sphere_inertia(m, r));
    for (int d = 0; d < film_dofs; d++) {
      s.velocity.push_back(g(rng));
      s.force.push_back(forces ? 10.0 * g(rng) : 0.0);
    }
  }
  for (int k = 0; k < n_pairs + n_walls; k++) {
    FilmLink l;
    l.i = int(u(rng) * n);
    l.j = k < n_pairs ? int(u(rng) * n) : -1;
    if (l.j == l.i) l.j = (l.i + 1) % n;
    l.normal = random_unit(rng);
    const double inverse_me = s.inverse_mass[l.i] + (l.j >= 0 ? s.inverse_mass[l.j] : 0.0) + 1e-3;
    l.normal_damping = max_share * std::pow(u(rng), 3) / (dt * inverse_me);
    l.shear_damping = max_share * std::pow(u(rng), 3) / (dt * inverse_me);
    if (l.j < 0) l.wall_velocity = {g(rng), g(rng), g(rng)};
    s.links.push_back(l);
  }
  return s;
}

// The film's rows: B_k w for its normal (u_n) and shear (s, 3 rows) relative velocities, and the
// wall's part of them, written out here from tangential.h's definitions.
struct Rows {
  std::vector<std::vector<double>> b;    // 4 rows of 6 n
  double offset[4];
  double coefficient[4];
};
inline Rows film_rows(const System &s, const FilmLink &l)
{
  const int size = film_dofs * s.n();
  Rows r;
  r.b.assign(4, std::vector<double>(size, 0.0));
  const double n[3] = {l.normal.x, l.normal.y, l.normal.z},
               wall[3] = {l.wall_velocity.x, l.wall_velocity.y, l.wall_velocity.z};
  for (int a = 0; a < 3; a++) {
    r.b[0][6 * l.i + a] = n[a];
    if (l.j >= 0) r.b[0][6 * l.j + a] = -n[a];
  }
  r.offset[0] = l.j >= 0 ? 0.0 : -(n[0] * wall[0] + n[1] * wall[1] + n[2] * wall[2]);
  r.coefficient[0] = l.normal_damping;
  // s_a = (P_t dv)_a - ((R_i omega_i + R_j omega_j) x n)_a, (omega x n)_a = eps_abc omega_b n_c.
  for (int a = 0; a < 3; a++) {
    r.offset[1 + a] = 0.0;
    r.coefficient[1 + a] = l.shear_damping;
    for (int b = 0; b < 3; b++) {
      const double tangent = (a == b) - n[a] * n[b];
      r.b[1 + a][6 * l.i + b] = tangent;
      if (l.j >= 0)
        r.b[1 + a][6 * l.j + b] = -tangent;
      else
        r.offset[1 + a] -= tangent * wall[b];
      const int c = 3 - a - b;
      if (a == b) continue;
      const double eps = ((b - a + 3) % 3 == 1) ? 1.0 : -1.0;    // eps_abc
      r.b[1 + a][6 * l.i + 3 + b] = -eps * s.radius[l.i] * n[c];
      if (l.j >= 0) r.b[1 + a][6 * l.j + 3 + b] = -eps * s.radius[l.j] * n[c];
    }
  }
  return r;
}

// Immovable atoms at rest and walls still: no work from outside, for the energy tests.
inline void at_rest_outside(System &s)
{
  for (FilmLink &l : s.links)
    l.wall_velocity = {};
  for (int e = 0; e < 6 * s.n(); e++)
    if ((e % 6 < 3 ? s.inverse_mass[e / 6] : s.inverse_inertia[e / 6]) == 0.0) s.velocity[e] = 0.0;
}

// Dense backward-Euler step: (M + dt R) w' = M w + dt (F + f_wall) over the movable components
// (immovable ones keep w). Returns w'.
inline std::vector<double> dense_step(const System &s, double dt)
{
  const int size = film_dofs * s.n();
  std::vector<double> a(size * size, 0.0), rhs(size, 0.0);
  std::vector<int> movable;
  for (int e = 0; e < size; e++) {
    const double inverse = e % 6 < 3 ? s.inverse_mass[e / 6] : s.inverse_inertia[e / 6];
    if (inverse > 0.0) movable.push_back(e);
    a[e * size + e] = inverse > 0.0 ? 1.0 / inverse : 1.0;
    rhs[e] = inverse > 0.0 ? a[e * size + e] * s.velocity[e] + dt * s.force[e] : s.velocity[e];
    if (s.drag.empty() || inverse == 0.0) continue;
    // The drag -c v is in F at w (explicit part); implicit: -c w'.
    const double c = e % 6 < 3 ? s.drag[e / 6] : s.rotational_drag[e / 6];
    a[e * size + e] += dt * c;
    rhs[e] += dt * c * s.velocity[e];
  }
  for (const FilmLink &l : s.links) {
    const Rows r = film_rows(s, l);
    for (int q = 0; q < 4; q++)
      for (int e = 0; e < size; e++) {
        if (r.b[q][e] == 0.0) continue;
        rhs[e] -= dt * r.coefficient[q] * r.offset[q] * r.b[q][e];
        for (int f = 0; f < size; f++)
          a[e * size + f] += dt * r.coefficient[q] * r.b[q][e] * r.b[q][f];
      }
  }
  // Fixed components: move their known values to the right-hand side.
  const int m = int(movable.size());
  std::vector<double> reduced(m * m), b(m);
  for (int p = 0; p < m; p++) {
    b[p] = rhs[movable[p]];
    for (int e = 0; e < size; e++) {
      const double inverse = e % 6 < 3 ? s.inverse_mass[e / 6] : s.inverse_inertia[e / 6];
      if (inverse == 0.0) b[p] -= a[movable[p] * size + e] * s.velocity[e];
    }
    for (int q = 0; q < m; q++)
      reduced[p * m + q] = a[movable[p] * size + movable[q]];
  }
  film_cholesky(reduced.data(), m);    // the test's own check of it: the residual below
  std::vector<double> x = b;
  film_cholesky_solve(reduced.data(), m, x.data());
  std::vector<double> out = s.velocity;
  for (int p = 0; p < m; p++)
    out[movable[p]] = x[p];
  // Residual of the dense solve itself, so that the Cholesky helpers are checked independently.
  double worst = 0.0, scale = 0.0;
  for (int e = 0; e < size; e++) {
    double row = -rhs[e];
    for (int f = 0; f < size; f++)
      row += a[e * size + f] * out[f];
    const double inverse = e % 6 < 3 ? s.inverse_mass[e / 6] : s.inverse_inertia[e / 6];
    if (inverse > 0.0) worst = std::max(worst, std::fabs(row)), scale = std::max(scale, std::fabs(rhs[e]));
  }
  EXPECT_LT(worst, 1e-11 * scale);
  return out;
}

inline std::vector<double> film_step(const System &s, double dt, FilmSolveResult *result = nullptr,
                                     FilmSolveOptions options = {})
{
  if (options.tolerance == FilmSolveOptions{}.tolerance) options.tolerance = 1e-13;
  options.max_iterations = std::max(options.max_iterations, 2000);
  std::vector<double> x(s.velocity.size());
  FilmSolver solver;
  const FilmSolveResult r = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(),
                                         s.force.data(), x.data(), options);
  if (result) *result = r;
  for (size_t e = 0; e < x.size(); e++)
    x[e] += s.velocity[e];
  return x;
}

inline double relative_difference(const std::vector<double> &a, const std::vector<double> &b)
{
  double d = 0.0, n = 0.0;
  for (size_t e = 0; e < a.size(); e++)
    d += (a[e] - b[e]) * (a[e] - b[e]), n += b[e] * b[e];
  return std::sqrt(d / n);
}

inline double kinetic_energy(const System &s, const std::vector<double> &w)
{
  double e = 0.0;
  for (int i = 0; i < s.n(); i++)
    for (int d = 0; d < film_dofs; d++) {
      const double inverse = d < 3 ? s.inverse_mass[i] : s.inverse_inertia[i];
      if (inverse > 0.0) e += 0.5 * w[6 * i + d] * w[6 * i + d] / inverse;
    }
  return e;
}

}    // namespace film_solve_test
