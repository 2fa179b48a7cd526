// Random coefficients over their whole allowed ranges (validate() decides what is allowed)
// and random states, far past the usual ones. The normal model must give finite parts, a
// spring energy >= 0 and a film that never reverses the relative motion within a step
// (|F_l| dt <= m_e |u_n| at a step, the caps of normal_model.h at a run start); the
// tangential parts must stay finite, within their caps and never reverse the slip; the drag
// coefficient must be finite and positive.
#include "lubricated/drag.h"
#include "lubricated/normal_model.h"
#include "lubricated/tangential.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

using namespace lubricated;

namespace {

struct Draw {
  std::mt19937_64 rng{20261123};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, uniform(0.0, 1.0)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
};

Coefficients random_coefficients(Draw &d)
{
  Coefficients c;
  c.e_dry = d.chance(0.1) ? 1.0 : d.log_uniform(1e-4, 1.0);
  c.n_contact = d.chance(0.1) ? 1.0 : d.log_uniform(1.0, 128.0);
  if (d.chance(0.5)) {
    c.viscosity = d.log_uniform(1e-6, 10.0);
    c.eps_saturation = d.log_uniform(1e-6, 0.1);
    if (d.chance(0.3)) c.grid_spacing = d.log_uniform(1e-6, 1e-1);    // some below eps_1 R
    else c.eps_activation = d.uniform(c.eps_saturation, 1.0);
    c.eps_release = d.chance(0.5) ? d.uniform(-0.1, 0.0) : d.uniform(0.0, c.eps_saturation);
    if (d.chance(0.3) && c.eps_release >= 0.0) c.legendre = d.chance(0.5) ? 35.0 : d.log_uniform(0.1, 1e3);
  }
  c.exact_contact = c.legendre > 0.0 || d.chance(0.8);
  return c;
}

}    // namespace

TEST(RandomInputs, NormalForceIsFiniteAndTheFilmNeverReversesTheMotion)
{
  Draw d;
  const Evaluation whens[] = {Evaluation::step, Evaluation::verlet_start, Evaluation::midpoint_start};
  int evaluated = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Coefficients c = random_coefficients(d);
    if (!validate(c).empty()) continue;
    const double dt = d.log_uniform(1e-9, 1e-1);
    const Partner partner = d.chance(0.5) ? Partner::wall : Partner::particle;
    const NormalModel m = make_normal_model(c, partner, dt);
    for (int state = 0; state < 50; ++state) {
      const double radius = d.log_uniform(1e-7, 1.0);
      const double mass = d.log_uniform(1e-15, 1e3);
      // Gaps from deep overlap to well past the film; speeds from creeping to crossing the
      // radius many times in one step, both signs.
      const double gap = radius * (d.chance(0.3) ? d.uniform(-0.5, 0.0) : d.log_uniform(1e-9, 2.0));
      const double speed = radius / dt * d.log_uniform(1e-12, 10.0);
      const double u_n = d.chance(0.5) ? speed : -speed;
      const Evaluation when = whens[state % 3];
      const NormalForce f = normal_force(m, gap, radius, mass, u_n, when);
      std::ostringstream where;
      where << "e_d " << c.e_dry << " N_c " << c.n_contact << " mu " << c.viscosity << " eps_al "
            << c.eps_activation << " dx " << c.grid_spacing << " eps_1 " << c.eps_saturation
            << " eps_2 " << c.eps_release << " A " << c.legendre << " exact " << c.exact_contact
            << " dt " << dt << " R " << radius << " m " << mass << " gap " << gap << " u_n "
            << u_n << " when " << static_cast<int>(when);
      ASSERT_TRUE(std::isfinite(f.contact) && std::isfinite(f.lubrication) && std::isfinite(f.energy))
          << where.str();
      ASSERT_GE(f.energy, 0.0) << where.str();
      if (c.wet()) {
        // The film may stop the motion over the step (a run start: over the half kick, or the
        // half drift of the midpoint scheme), never reverse it; it always opposes u_n.
        const double cap = when == Evaluation::step ? 1.0 : when == Evaluation::verlet_start ? 2.0 : 4.0;
        if (c.exact_contact || when == Evaluation::midpoint_start) {
          ASSERT_LE(std::fabs(f.lubrication) * dt, cap * mass * speed * (1.0 + 1e-12)) << where.str();
        }
        ASSERT_LE(f.lubrication * u_n, 0.0) << where.str();
      }
      ++evaluated;
    }
  }
  EXPECT_GT(evaluated, 50000);    // most draws are valid: the test covers what it claims
}

namespace {

Vec3 random_vector(Draw &d, double size)
{
  return {size * d.uniform(-1.0, 1.0), size * d.uniform(-1.0, 1.0), size * d.uniform(-1.0, 1.0)};
}

double length(const Vec3 &a) { return std::sqrt(dot(a, a)); }

}    // namespace

TEST(RandomInputs, TangentialForcesAreFiniteAndNeverReverseTheSlip)
{
  Draw d;
  int evaluated = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Coefficients c = random_coefficients(d);
    c.friction = d.chance(0.2) ? 0.0 : d.log_uniform(1e-3, 10.0);
    if (d.chance(0.7)) c.e_tangential = d.chance(0.1) ? 0.0 : d.uniform(0.0, 1.0);
    c.rolling_friction = d.chance(0.5) ? 0.0 : d.log_uniform(1e-4, 1.0);
    c.shearfilm = d.chance(0.5) ? 1 : -1;
    if (!validate(c).empty()) continue;
    const double dt = d.log_uniform(1e-9, 1e-1);
    const TangentialModel tm = make_tangential_model(c, dt);
    const Lubrication film = make_lubrication(Partner::particle, c.viscosity, c.eps_activation,
                                              c.grid_spacing, c.eps_saturation, c.eps_release);
    for (int state = 0; state < 50; ++state) {
      const double radius = d.log_uniform(1e-7, 1.0), mass = d.log_uniform(1e-15, 1e3);
      const double m_t = tangential_mass_ratio * mass;
      Vec3 n = random_vector(d, 1.0);
      if (length(n) < 1e-3) continue;
      n = scaled(n, 1.0 / length(n));
      const Vec3 s = tangential_part(random_vector(d, radius / dt * d.log_uniform(1e-12, 10.0)), n);
      const double normal = mass * radius / (dt * dt) * d.log_uniform(1e-12, 10.0);
      if (tm.contact_active()) {
        Vec3 delta = random_vector(d, radius * d.log_uniform(1e-12, 1.0));
        const Vec3 f = tangential_contact_force(tm, delta, n, s, m_t, normal, d.uniform(0.0, 1.0));
        ASSERT_TRUE(std::isfinite(length(f)) && std::isfinite(length(delta)));
        ASSERT_LE(length(f), c.friction * normal * (1.0 + 1e-12));
      }
      if (tm.rolling_active()) {
        const double inertia = 0.2 * mass * radius * radius;
        const Vec3 w = tangential_part(random_vector(d, d.log_uniform(1e-12, 10.0) / dt), n);
        const Vec3 t = rolling_torque(tm, n, w, 0.5 * radius, inertia, normal);
        ASSERT_TRUE(std::isfinite(length(t)));
        ASSERT_LE(length(t) * dt, inertia * length(w) * (1.0 + 1e-12));    // never reverses w
      }
      if (tm.film_active()) {
        const double eps = d.chance(0.3) ? d.uniform(-0.5, 0.0) : d.log_uniform(1e-9, 2.0);
        const Vec3 f = shear_film_force(tm, s, eps, film.activation_for(radius), film.eps_saturation,
                                        film.eps_release, 0.5 * radius, m_t);
        ASSERT_TRUE(std::isfinite(length(f)));
        ASSERT_LE(dot(f, s), 0.0) << "eps " << eps << " eps_al " << film.activation_for(radius);
        ASSERT_LE(length(f) * dt, m_t * length(s) * (1.0 + 1e-12));
      }
      ++evaluated;
    }
  }
  EXPECT_GT(evaluated, 50000);
}

TEST(RandomInputs, DragCoefficientIsFiniteAndPositive)
{
  Draw d;
  const DragLaw laws[] = {DragLaw::stokes, DragLaw::schiller_naumann};
  const Hindrance hindrances[] = {Hindrance::none, Hindrance::richardson_zaki, Hindrance::di_felice};
  for (int trial = 0; trial < 100000; ++trial) {
    DragModel m;
    m.viscosity = d.log_uniform(1e-7, 1e3);
    m.density = d.chance(0.1) ? 0.0 : d.log_uniform(1e-3, 1e5);
    m.law = laws[trial % 2];
    m.hindrance = hindrances[(trial / 2) % 3];
    m.rz_exponent = d.uniform(1.0, 6.0);
    const double diameter = d.log_uniform(1e-9, 1.0);
    const double slip = d.chance(0.1) ? 0.0 : d.log_uniform(1e-15, 1e4);
    const double voidage = d.chance(0.1) ? 0.0 : d.uniform(-0.5, 1.5);    // clamped inside
    const double beta = drag_beta(m, diameter, slip, voidage);
    ASSERT_TRUE(std::isfinite(beta) && beta > 0.0)
        << "mu " << m.viscosity << " rho " << m.density << " d " << diameter << " w " << slip
        << " voidage " << voidage << " law " << trial % 2 << " hindrance " << (trial / 2) % 3;
  }
}
