// A sphere resting on several walls at once (a V-groove, a corner) under a steady acceleration g
// (gravity): the walls together hold it, so the steady loads b_k of its contacts along their
// normals n_k (from the wall to the sphere) are the non-negative solution of sum_k b_k n_k = -g,
// least squares over the touching faces (at most three). One face alone takes b = -g . n (its
// projection); two faces of a 60 degree groove share the weight instead of each taking it whole,
// which over-pushed the loaded event steps and let a resting sphere rise (doc/model.rst,
// "Contacts under a steady load").
#pragma once

#include "lubricated/tangential.h"

#include <cmath>

namespace lubricated {

constexpr int max_shared_loads = 3;

namespace detail {
// Least squares over the faces in `subset` (a bit mask of n < 4 faces): the normal equations
// G b = -N^T g, solved by Cramer's rule. False where the normals are (nearly) dependent.
inline bool loads_on_subset(const Vec3 *normal, int count, unsigned subset, const Vec3 &g, double *b)
{
  int index[max_shared_loads], m = 0;
  for (int k = 0; k < count; k++)
    if (subset & (1u << k)) index[m++] = k;
  double gram[3][3] = {}, rhs[3] = {};
  for (int r = 0; r < m; r++) {
    rhs[r] = -dot(normal[index[r]], g);
    for (int c = 0; c < m; c++)
      gram[r][c] = dot(normal[index[r]], normal[index[c]]);
  }
  for (int r = m; r < 3; r++)
    gram[r][r] = 1.0;    // unused rows: identity
  auto det3 = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double det = det3(gram);
  if (!(det > 1e-12)) return false;    // unit normals: det = 1 - cos^2 ... is well scaled
  for (int r = 0; r < m; r++) {
    double column[3][3];
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        column[i][j] = j == r ? rhs[i] : gram[i][j];
    b[index[r]] = det3(column) / det;
  }
  return true;
}
}    // namespace detail

// The steady loads (count <= max_shared_loads unit normals, acceleration g): b_k >= 0 with
// sum b_k n_k closest to -g. Every subset of the faces is solved (at most seven small systems);
// the feasible one with the smallest residual wins (the non-negative least-squares solution).
inline void shared_loads(const Vec3 *normal, int count, const Vec3 &g, double *load)
{
  double best = INFINITY;
  for (int k = 0; k < count; k++)
    load[k] = 0.0;
  for (unsigned subset = 1; subset < (1u << count); subset++) {
    double b[max_shared_loads] = {};
    if (!detail::loads_on_subset(normal, count, subset, g, b)) continue;
    bool feasible = true;
    Vec3 sum = g;
    for (int k = 0; k < count; k++) {
      feasible = feasible && b[k] >= 0.0;
      sum = plus(sum, scaled(normal[k], b[k]));
    }
    const double residual = dot(sum, sum);
    if (feasible && residual < best) {
      best = residual;
      for (int k = 0; k < count; k++)
        load[k] = b[k];
    }
  }
}

}    // namespace lubricated
