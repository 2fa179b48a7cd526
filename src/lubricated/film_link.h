// A pair's films as one link of the coupled film solve (film_solve.h, doc/film_solve.rst): the
// normal film's coefficient c_n (Lubrication::damping), the shear film's raw coefficient c_t
// and the rolling film's gamma (tangential.h) at the step's gap. The engines' pair loops apply
// the films step-exact; where a sphere's film budget binds they hand the pair's films to the
// solve with these coefficients instead.
#pragma once

#include "lubricated/contact.h"
#include "lubricated/film_solve.h"

#include <algorithm>
#include <cmath>

namespace lubricated {

// The shear film's coefficient c_t = 2 pi mu_f R_e ln(eps_al / max(eps, eps_1)) for
// eps_2 < eps < eps_al, else 0: the linear damper of tangential.h's shear_film_force before its
// exact integration over the step (the implicit solve is stable by itself).
inline double shear_film_coefficient(const TangentialModel &m, double eps, double eps_al, double eps_saturation,
                                     double eps_release, double reduced_radius)
{
  if (!m.film_active() || !(eps < eps_al && eps > eps_release)) return 0.0;
  return m.two_pi_mu * reduced_radius * std::log(eps_al / std::max(eps, eps_saturation));
}

// The link of the films of spheres i (radius_i) and j at centre distance r with unit normal n
// from j to i, for the model of their type pair.
inline FilmLink pair_film_link(const ContactModel &model, int i, int j, const Vec3 &n, double r, double radius_i,
                               double radius_j)
{
  FilmLink link;
  link.i = i, link.j = j, link.normal = n;
  const Lubrication &film = model.normal.lubrication;
  if (!film.active()) return link;
  const FilmRadius radius = film_radius_pair(radius_i, radius_j);
  const double eps = (r - radius_i - radius_j) / radius.value;
  const double eps_al = film.activation_for(radius.value), reduced_radius = radius_i * radius_j / (radius_i + radius_j);
  link.normal_damping = film.damping(eps, radius.value);
  link.shear_damping =
      shear_film_coefficient(model.tangential, eps, eps_al, film.eps_saturation, film.eps_release, reduced_radius);
  if (model.tangential.roll_film_active())
    link.roll_damping = roll_film_coefficient(model.tangential.roll_mu, eps, eps_al, film.eps_saturation,
                                              film.eps_release, reduced_radius);
  return link;
}

// A wall's films on sphere i as a link (j = -1): the gap and the unit normal n from the wall to
// the sphere, the normal film's radius R_f, the shear film's radius, and the wall's surface
// velocity at the contact (wall_velocity_at_contact). A wall has no rolling film.
inline FilmLink wall_film_link(const ContactModel &model, int i, const Vec3 &n, double gap, const FilmRadius &radius,
                               double shear_radius, const Vec3 &wall_velocity)
{
  FilmLink link;
  link.i = i, link.j = -1, link.normal = n, link.wall_velocity = wall_velocity;
  const Lubrication &film = model.normal.lubrication;
  if (!film.active()) return link;
  const double eps = gap / radius.value;
  link.normal_damping = film.damping(eps, radius.value);
  link.shear_damping = shear_film_coefficient(model.tangential, eps, film.activation_for(radius.value),
                                              film.eps_saturation, film.eps_release, shear_radius);
  return link;
}

// The wall's surface velocity v_w at a contact, from what a wall fix hands the contact: the
// sphere's velocity v, spin omega and radius R, the relative normal velocity u_n (along n, from
// the wall to the sphere) and, where the contact has tangential parts, the relative dv' and
// omega' of relative_to_wall (wall_motion.h; nullptr: none). Its normal part v.n - u_n keeps the
// link's u_n the contact's; its tangential part makes the link's slip P_t (v - v_w) - R omega x n
// the contact's P_t dv' - R omega' x n (a turning wall included).
inline Vec3 wall_velocity_at_contact(const Vec3 &v, const Vec3 &omega, double radius, const Vec3 &n, double u_n,
                                     const Vec3 *dv, const Vec3 *omega_relative)
{
  const Vec3 normal = scaled(n, dot(v, n) - u_n);
  if (!dv) return normal;
  const Vec3 spin_of_wall = minus(omega, *omega_relative);
  return plus(normal, tangential_part(minus(minus(v, *dv), scaled(cross(spin_of_wall, n), radius)), n));
}

}    // namespace lubricated
