// Cavitation of a separating film (doc/fix_wall_lubrication.rst, keyword cavitation; doc/model.rst,
// "Rebound in a viscous liquid"). Reynolds' equation for a sphere of radius R leaving a plane at
// the speed u (gap h(r) = h + r^2 / (2R)) gives the film pressure p - p_0 = -3 mu R u / h(r)^2:
// a tension, -6 pi mu R^2 u / h over the film, that grows without bound as h -> 0. A liquid
// cannot be pulled more than dp_c below its ambient pressure (dp_c = p_0 - p_cav, about the
// ambient pressure where vapour or dissolved gas cavitates): where the Reynolds pressure would
// fall below, the film cavitates and holds -dp_c (the half-Sommerfeld condition of lubrication
// theory). That region is r < r_c, h(r_c) = h_c = sqrt(3 mu R u / dp_c), and the film's force is
//   F = -2 pi R dp_c (2 h_c - h)    for h < h_c   (continuous at h_c with -6 pi mu R^2 u / h),
// the same Reynolds force beyond. Cavities on a sphere's rebound from a wetted wall: Mansoor et
// al. (2014, Exp. Fluids 55:1648, after contact, on depressurisation); a cavity in the diverging
// film between a sphere and a wall: Ashmore, del Pino & Mullin (2005, Phys. Rev. Lett. 94:124501);
// the tension that a separating elastohydrodynamic film exerts: Davis, Serayssol & Hinch (1986,
// J. Fluid Mech. 163:479); film rupture near the ambient pressure in bearings (gaseous cavitation of
// the dissolved air): Dowson & Taylor (1979, Annu. Rev. Fluid Mech. 11:35). dp_c = 0 is that
// limit (h_c -> infinity: the Reynolds tension is removed at every gap). An approaching film
// (compression) is unaffected.
#pragma once

#include <algorithm>
#include <cmath>

namespace lubricated {

// The part of a separating film's tension that cavitation removes [force, >= 0]: the leading
// Reynolds term 6 pi mu R^2 u / h less the cavitated film's 2 pi R dp_c (2 h_c - h), never more
// than the film force itself (film_force: the film's force along n, < 0 on separation).
// six_pi_mu: 6 pi mu_f; radius: the film's R; gap: the film's gap (held at eps_1 R below it, as
// the film is); u_n: the separation speed (> 0 apart); dp_c: the tension limit (< 0: none, the film
// as it is; 0: the film ruptures at the ambient pressure and holds no Reynolds tension).
inline double cavitation_relief(double six_pi_mu, double radius, double gap, double u_n, double dp_c, double film_force)
{
  if (!(dp_c >= 0.0) || !(u_n > 0.0) || !(film_force < 0.0) || !(gap > 0.0)) return 0.0;
  constexpr double two_pi = 6.283185307179586;
  const double tension = six_pi_mu * radius * radius * u_n / gap;
  if (dp_c == 0.0) return std::min(tension, -film_force);                      // a film that ruptures at once
  const double h_c = std::sqrt(six_pi_mu * radius * u_n / (two_pi * dp_c));    // 3 mu R u / dp_c
  if (gap >= h_c) return 0.0;
  const double cavitated = two_pi * radius * dp_c * (2.0 * h_c - gap);
  return std::min(std::max(tension - cavitated, 0.0), -film_force);
}

}    // namespace lubricated
