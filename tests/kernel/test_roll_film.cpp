// The rolling film (tangential.h, roll_film_coefficient) against Jeffrey & Onishi's leading
// logarithms of two spheres (radii a and lambda a), as the literature tabulates them
// (normalisations: A_11 by 6 pi mu a, B_11 by 4 pi mu a^2, C_11 by 8 pi mu a^3, C_12 by
// pi mu (a + lambda a)^3; sphere 2 by lambda -> 1 / lambda and a -> lambda a).
#include "lubricated/check_setup.h"
#include "lubricated/film_link.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {

double ya11(double l)
{
  return 4.0 / 15.0 * l * (2.0 + l + 2.0 * l * l) / std::pow(1.0 + l, 3);
}
double yb11(double l)
{
  return -0.2 * l * (4.0 + l) / std::pow(1.0 + l, 2);
}
double yc11(double l)
{
  return 0.4 * l / (1.0 + l);
}
double yc12(double l)
{
  return 0.8 * l * l / std::pow(1.0 + l, 4);
}

}    // namespace

// In one tangent direction (slip along x, spins about y, n along z) the films' dissipation
// alpha s^2 + 2 beta s w + gamma w^2, s = v_1 - v_2 - a_1 w_1 - a_2 w_2 and w = w_1 - w_2, gives
// every coupling of the two spheres: alpha from A_11 and beta from B_11 fix the slip part, and
// gamma, the rolling film, must then return C_11, C_12 and C_22 (and B_22) for every ratio.
TEST(RollFilm, CompletesJeffreyOnishiForAnySizeRatio)
{
  const double mu = 1.3, a1 = 0.7, eps = 1e-3, log_inverse = std::log(1.0 / eps);
  for (double l : {0.25, 0.7, 1.0, 1.4, 4.0}) {
    const double a2 = l * a1, r_e = a1 * a2 / (a1 + a2);
    const double alpha = ya11(l) * 6.0 * pi * mu * a1 * log_inverse;
    // Force on 1 from spin 1: alpha a1 - beta (the Rayleigh form) = -B_11.
    const double beta = alpha * a1 + yb11(l) * 4.0 * pi * mu * a1 * a1 * log_inverse;
    // roll_film_coefficient with eps_al = 1 and no saturation: ln(1 / eps).
    const double gamma = roll_film_coefficient(mu, eps, 1.0, 0.0, -1.0, r_e);
    const double c11 = a1 * a1 * alpha - 2.0 * a1 * beta + gamma;     // -dT_1/dw_1
    const double c12 = a1 * a2 * alpha + (a1 - a2) * beta - gamma;    // -dT_1/dw_2
    const double c22 = a2 * a2 * alpha + 2.0 * a2 * beta + gamma;     // -dT_2/dw_2
    const double b22 = a2 * alpha + beta;                             // -dF_2/dw_2
    const double scale = pi * mu * log_inverse;
    EXPECT_NEAR(c11, yc11(l) * 8.0 * scale * a1 * a1 * a1, 1e-12 * c11) << l;
    EXPECT_NEAR(c12, yc12(l) * scale * std::pow(a1 + a2, 3), 1e-12 * c11) << l;
    EXPECT_NEAR(c22, yc11(1.0 / l) * 8.0 * scale * a2 * a2 * a2, 1e-12 * c22) << l;
    EXPECT_NEAR(b22, -yb11(1.0 / l) * 4.0 * scale * a2 * a2, 1e-12 * std::fabs(b22)) << l;
    EXPECT_GT(gamma, 0.0);
  }
}

// Equal spheres: the shear film is Jeffrey & Onishi's slip term (beta = 0) and the rolling
// film the (3/40) ln(1/eps) 8 pi mu a^3 that C_11 = 1/5 and C_12 = 1/20 leave beyond it.
TEST(RollFilm, EqualSpheres)
{
  const double mu = 0.01, a = 2e-4, eps = 1e-2;
  EXPECT_NEAR(roll_film_coefficient(mu, eps, 1.0, 0.0, -1.0, 0.5 * a),
              3.0 / 40.0 * 8.0 * pi * mu * a * a * a * std::log(1.0 / eps), 1e-24);
  EXPECT_NEAR(ya11(1.0) * 6.0 * a, 2.0 * (0.5 * a), 1e-18);    // the shear film's 2 pi mu R_e
}

TEST(RollFilm, ActsWhereTheShearFilmActs)
{
  EXPECT_EQ(roll_film_coefficient(1.0, 0.2, 0.1, 1e-3, 1e-4, 1.0), 0.0);      // beyond activation
  EXPECT_EQ(roll_film_coefficient(1.0, 5e-5, 0.1, 1e-3, 1e-4, 1.0), 0.0);     // released
  EXPECT_DOUBLE_EQ(roll_film_coefficient(1.0, 5e-4, 0.1, 1e-3, 1e-4, 1.0),    // saturated
                   roll_film_coefficient(1.0, 1e-3, 0.1, 1e-3, 1e-4, 1.0));
  EXPECT_EQ(roll_film_coefficient(1.0, 0.1, 0.1, 1e-3, 1e-4, 1.0), 0.0);    // continuous at eps_al
}

// The whole contact (contact.h) of a wet pair at rest with `rollfilm yes`: the rolling film's
// couple on i and j (no force), exactly the step-exact damper of the relative spin across n.
TEST(RollFilm, ContactAppliesTheStepExactCouple)
{
  Coefficients c;
  c.e_dry = 0.5, c.n_contact = 8, c.viscosity = 0.01, c.eps_activation = 0.1, c.shearfilm = 0, c.rollfilm = 1;
  ASSERT_TRUE(c.tangential());
  const double dt = 1e-6, r_i = 1e-3, r_j = 1.4e-3, rho = 1000.0;
  const ContactModel model = make_contact_model(c, Partner::particle, dt);
  ContactPoint p;
  p.film = film_radius_pair(r_i, r_j);
  p.gap = 0.01 * p.film.value;
  p.n = {1.0, 0.0, 0.0};
  p.omega_i = {3.0, 2.0, 0.5}, p.omega_j = {-1.0, 0.0, 1.0};
  p.radius_i = r_i, p.radius_j = r_j, p.reduced_radius = r_i * r_j / (r_i + r_j);
  p.mass_i = rho * 4.0 / 3.0 * pi * r_i * r_i * r_i, p.mass_j = rho * 4.0 / 3.0 * pi * r_j * r_j * r_j;
  p.reduced_mass = p.mass_i * p.mass_j / (p.mass_i + p.mass_j);
  HistorySlot slot;
  const ContactForces f = contact_forces<true>(model, p, slot);
  const double gamma = roll_film_coefficient(c.viscosity, 0.01, 0.1, c.eps_saturation, c.eps_release, p.reduced_radius);
  const double inertia = 1.0 / (1.0 / sphere_inertia(p.mass_i, r_i) + 1.0 / sphere_inertia(p.mass_j, r_j));
  const double damping = -std::expm1(-gamma * dt / inertia) * inertia / dt;
  EXPECT_NEAR(f.torque_i.x, 0.0, 0.0);
  EXPECT_NEAR(f.torque_i.y, -damping * 2.0, 1e-12 * damping);
  EXPECT_NEAR(f.torque_i.z, -damping * -0.5, 1e-12 * damping);
  EXPECT_DOUBLE_EQ(f.torque_j.y, -f.torque_i.y);
  EXPECT_DOUBLE_EQ(f.torque_j.z, -f.torque_i.z);
  EXPECT_DOUBLE_EQ(f.roll_film.y, f.torque_i.y);
  EXPECT_EQ(dot(f.tangential, f.tangential), 0.0);
  // its share of the budget: the fraction of the relative spin one step removes
  EXPECT_NEAR(f.shear_share(dt), -std::expm1(-gamma * dt / inertia), 1e-14);
}

// The coupled solve's link carries the rolling film's gamma: a couple -gamma w on i, +gamma w on j,
// dissipating gamma |w|^2.
TEST(RollFilm, FilmLinkCarriesTheCouple)
{
  Coefficients c;
  c.e_dry = 0.5, c.n_contact = 8, c.viscosity = 0.01, c.eps_activation = 0.1, c.shearfilm = 0, c.rollfilm = 1;
  const ContactModel model = make_contact_model(c, Partner::particle, 1e-6);
  const double r_i = 1e-3, r_j = 1.4e-3, eps = 0.01;
  const double r = r_i + r_j + eps * film_radius_pair(r_i, r_j).value;
  const FilmLink link = pair_film_link(model, 0, 1, {0.0, 0.0, 1.0}, r, r_i, r_j);
  const double gamma =
      roll_film_coefficient(c.viscosity, eps, 0.1, c.eps_saturation, c.eps_release, r_i * r_j / (r_i + r_j));
  EXPECT_NEAR(link.roll_damping, gamma, 1e-12 * gamma);    // eps from the centre distance
  EXPECT_EQ(link.shear_damping, 0.0);
  const double radius[2] = {r_i, r_j}, w[12] = {0, 0, 0, 1.0, -2.0, 4.0, 0, 0, 0, 0.5, 1.0, -3.0};
  FilmAtoms atoms;
  atoms.owned = atoms.total = 2, atoms.radius = radius;
  const FilmLinkForce f = film_link_force(link, atoms, w, true);
  EXPECT_NEAR(f.torque_i.x, -link.roll_damping * 0.5, 1e-15);
  EXPECT_NEAR(f.torque_i.y, -link.roll_damping * -3.0, 1e-15);
  EXPECT_EQ(f.torque_i.z, 0.0);
  EXPECT_DOUBLE_EQ(f.torque_j.x, -f.torque_i.x);
  EXPECT_DOUBLE_EQ(f.torque_j.y, -f.torque_i.y);
  const double power = dot(f.torque_i, {1.0, -2.0, 4.0}) + dot(f.torque_j, {0.5, 1.0, -3.0});
  EXPECT_NEAR(power, -link.roll_damping * (0.25 + 9.0), 1e-15);
}

TEST(RollFilm, WallsRefuseIt)
{
  Coefficients c;
  c.e_dry = 0.5, c.n_contact = 8, c.viscosity = 0.01, c.eps_activation = 0.1, c.rollfilm = 1;
  EXPECT_NE(check_setup(c, Partner::wall, 1e-6).error.find("rollfilm is for pairs of spheres"), std::string::npos);
  EXPECT_EQ(check_setup(c, Partner::particle, 1e-6).error, "");
}
