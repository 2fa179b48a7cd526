// The film radius of a sphere against a curved wall (cylinder, sphere, any region surface).
//
// Convention (doc/model.rst, "Curved walls"): a wall's principal radius of curvature R_w is
// positive where the wall is convex towards the sphere (the sphere outside a cylinder or a
// sphere), negative where it is concave (the sphere inside), and 0 for no curvature (a plane,
// a cylinder's axial direction). Lengths in the input's length unit.
//
// The gap near the closest point is h = h0 + x^2 / (2 a) + y^2 / (2 b), with the principal
// relative radii 1/a = 1/R + 1/R_w1 and 1/b = 1/R + 1/R_w2. Reynolds' squeeze-film equation
// scaled with x ~ sqrt(2 a h0), y ~ sqrt(2 b h0) gives the film force
//   F = 6 pi mu v a b / h0 * g(a/b),  g(1) = 1,  g(r) = g(1/r),
// so g = 1 + O(ln^2(a/b)): to second order in R / R_w the force is the flat-wall force of a
// sphere of radius R_f = sqrt(a b), the geometric mean. For a sphere region (a = b) this is
// exact in the lubrication limit; for a cylinder the error is O((R / R_w)^2).
// The film law lambda_pw(h / R_f) and its prefactor 6 pi mu R_f then take R_f in place of R.
#pragma once

#include <cmath>

namespace lubricated {

// Relative radius along one principal direction: R R_w / (R + R_w), R for a flat direction.
// Defined (positive) when the sphere fits: R_w > 0, R_w == 0, or R_w < -R (concave, larger).
inline double relative_radius(double sphere_radius, double wall_curvature_radius)
{
  if (wall_curvature_radius == 0.0) return sphere_radius;
  return sphere_radius * wall_curvature_radius / (sphere_radius + wall_curvature_radius);
}

// True where a sphere of radius R fits against the wall along that direction (a concave wall
// of radius |R_w| <= R cannot hold it: its relative radius would be infinite or negative).
inline bool sphere_fits_wall(double sphere_radius, double wall_curvature_radius)
{
  return wall_curvature_radius >= 0.0 || -wall_curvature_radius > sphere_radius;
}

// Film radius R_f = sqrt(a b) of a sphere against a wall of principal radii R_w1, R_w2.
inline double wall_film_radius(double sphere_radius, double wall_radius_1, double wall_radius_2)
{
  return std::sqrt(relative_radius(sphere_radius, wall_radius_1) * relative_radius(sphere_radius, wall_radius_2));
}

}    // namespace lubricated
