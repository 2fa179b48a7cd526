// Random coefficients over their whole allowed ranges (validate() decides what is allowed)
// and random states, far past the usual ones. The normal model must give finite parts, a
// spring energy >= 0 and a film that never reverses the relative motion within a step
// (|F_l| dt <= m_e |u_n| at a step, the caps of normal_model.h at a run start); the
// tangential parts must stay finite, within their caps and never reverse the slip; the drag
// coefficient must be finite and positive.
#include "lubricated/drag.h"
#include "lubricated/normal_model.h"
#include "lubricated/contact.h"

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

// extremes: a draw in five also reaches the ends of the allowed ranges (coefficients.h):
// e_d down to 1e-300, N_c up to 1e6, mu_f over 1e-100...1e100, eps_1 down to 1e-12.
Coefficients random_coefficients(Draw &d, bool extremes = false)
{
  Coefficients c;
  const bool far = extremes && d.chance(0.2);
  c.e_dry = d.chance(0.1) ? 1.0 : d.log_uniform(far ? 1e-300 : 1e-4, 1.0);
  c.n_contact = d.chance(0.1) ? 1.0 : d.log_uniform(1.0, far ? 1e6 : 128.0);
  if (d.chance(0.5)) {
    c.viscosity = far ? d.log_uniform(1e-100, 1e100) : d.log_uniform(1e-6, 10.0);
    c.eps_saturation = d.log_uniform(far ? 1e-12 : 1e-6, 0.1);
    if (d.chance(0.3))
      c.grid_spacing = d.log_uniform(1e-6, 1e-1);    // some below eps_1 R
    else
      c.eps_activation = d.uniform(c.eps_saturation, 1.0);
    c.eps_release = d.chance(0.5) ? d.uniform(-0.1, 0.0) : d.uniform(0.0, c.eps_saturation);
    if (d.chance(0.3) && c.eps_release >= 0.0)
      c.legendre = d.chance(0.5) ? 35.0 : d.log_uniform(0.1, far ? 1e300 : 1e3);
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
    const Coefficients c = random_coefficients(d, true);
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
      where << "e_d " << c.e_dry << " N_c " << c.n_contact << " mu " << c.viscosity << " eps_al " << c.eps_activation
            << " dx " << c.grid_spacing << " eps_1 " << c.eps_saturation << " eps_2 " << c.eps_release << " A "
            << c.legendre << " exact " << c.exact_contact << " dt " << dt << " R " << radius << " m " << mass << " gap "
            << gap << " u_n " << u_n << " when " << static_cast<int>(when);
      ASSERT_TRUE(std::isfinite(f.contact) && std::isfinite(f.lubrication) && std::isfinite(f.energy)) << where.str();
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

double length(const Vec3 &a)
{
  return std::sqrt(dot(a, a));
}

}    // namespace

TEST(RandomInputs, TangentialForcesAreFiniteAndNeverReverseTheSlip)
{
  Draw d;
  int evaluated = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Coefficients c = random_coefficients(d, true);
    c.friction = d.chance(0.2) ? 0.0 : d.log_uniform(1e-3, 10.0);
    if (d.chance(0.7)) c.e_tangential = d.chance(0.1) ? 0.0 : d.uniform(0.0, 1.0);
    c.rolling_friction = d.chance(0.5) ? 0.0 : d.log_uniform(1e-4, 1.0);
    c.shearfilm = d.chance(0.5) ? 1 : -1;
    if (!validate(c).empty()) continue;
    const double dt = d.log_uniform(1e-9, 1e-1);
    const TangentialModel tm = make_contact_model(c, Partner::particle, dt).tangential;
    const Lubrication film = make_lubrication(Partner::particle, c.viscosity, c.eps_activation, c.grid_spacing,
                                              c.eps_saturation, c.eps_release);
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
        const Vec3 f = shear_film_force(tm, s, eps, film.activation_for(radius), film.eps_saturation, film.eps_release,
                                        0.5 * radius, m_t);
        ASSERT_TRUE(std::isfinite(length(f)));
        ASSERT_LE(dot(f, s), 0.0) << "eps " << eps << " eps_al " << film.activation_for(radius);
        ASSERT_LE(length(f) * dt, m_t * length(s) * (1.0 + 1e-12));
      }
      ++evaluated;
    }
  }
  EXPECT_GT(evaluated, 50000);
}

// Every value validate() and validate_time_step() accept, however far from the usual, gives
// finite per-type-pair constants: k and c per unit mass, the per-step contact (ContactStep),
// lambda and its integral at eps_1 and eps_al, the film integral, the tangential constants.
// Draws span the whole double range (most are rejected: the point is what gets through).
TEST(RandomInputs, AcceptedCoefficientsGiveFiniteModelConstants)
{
  Draw d;
  int accepted = 0;
  // Log-uniform over any span of the double range; mostly near the allowed range [lo, hi]
  // (ten decades either side), else anywhere from 1e-320 to 1e300.
  auto wide = [&d](double lo, double hi) { return std::exp(d.uniform(std::log(lo), std::log(hi))); };
  auto near = [&](double lo, double hi) {
    return d.chance(0.8) ? wide(std::max(lo * 1e-10, 1e-320), std::min(hi * 1e10, 1e300)) : wide(1e-320, 1e300);
  };
  for (int trial = 0; trial < 1000000 && accepted < 3000; ++trial) {
    Coefficients c;
    c.e_dry = d.chance(0.1) ? 1.0 : wide(1e-320, 1.0);
    if (d.chance(0.5))
      c.n_contact = near(1.0, 1e6);
    else
      c.t_contact = near(1e-100, 1e100);
    const double dt = near(1e-106, 1e100);
    if (d.chance(0.7)) {
      c.viscosity = near(1e-100, 1e100);
      c.eps_saturation = near(1e-12, 1.0);
      if (d.chance(0.5))
        c.grid_spacing = near(1e-100, 1e100);
      else
        c.eps_activation = d.log_uniform(std::min(c.eps_saturation, 1.0), 1.0);
      c.eps_release = d.chance(0.5) ? -near(1e-100, 1e100) : d.uniform(0.0, c.eps_saturation);
      if (c.eps_release >= 0.0 && d.chance(0.5)) c.legendre = near(1e-10, 1e10);
    } else if (d.chance(0.5)) {
      c.eps_saturation = near(1e-12, 1.0);
    }
    c.friction = d.chance(0.5) ? 0.0 : near(1e-10, 1e10);
    if (d.chance(0.5)) c.e_tangential = d.chance(0.1) ? 0.0 : wide(1e-320, 1.0);
    c.rolling_friction = d.chance(0.5) ? 0.0 : near(1e-10, 1e10);
    if (!validate(c).empty() || !validate_time_step(c, dt).empty()) continue;
    ++accepted;
    std::ostringstream where;
    where << "e_d " << c.e_dry << " N_c " << c.n_contact << " t_c " << c.t_contact << " dt " << dt << " mu "
          << c.viscosity << " eps_al " << c.eps_activation << " dx " << c.grid_spacing << " eps_1 " << c.eps_saturation
          << " eps_2 " << c.eps_release << " A " << c.legendre;
    for (Partner partner : {Partner::particle, Partner::wall}) {
      const NormalModel m = make_normal_model(c, partner, dt);
      const SpringDashpot &sd = m.contact;
      ASSERT_TRUE(std::isfinite(sd.stiffness_per_mass) && sd.stiffness_per_mass > 0.0) << where.str();
      ASSERT_TRUE(std::isfinite(sd.damping_per_mass) && sd.damping_per_mass >= 0.0) << where.str();
      const ContactStep &cs = m.step;
      ASSERT_TRUE(std::isfinite(cs.inv_dt) && std::isfinite(cs.omega) && cs.omega > 0.0) << where.str();
      ASSERT_TRUE(std::isfinite(cs.decay_rate) && cs.decay_rate >= 0.0) << where.str();
      ASSERT_TRUE(cs.E >= 0.0 && cs.E <= 1.0 && std::isfinite(cs.C) && std::isfinite(cs.S)) << where.str();
      ASSERT_TRUE(std::isfinite(cs.stiffness_step) && cs.stiffness_step > 0.0) << where.str();
      ASSERT_TRUE(std::isfinite(cs.damping_step) && cs.damping_step >= 0.0) << where.str();
      for (int k = 0; k <= ContactStep::table_size; ++k)    // guesses in units of dt, within the step
        ASSERT_TRUE(cs.exit_guess[k] >= 0.0 && cs.exit_guess[k] <= 1.0 && cs.entry_guess[k] >= 0.0 &&
                    cs.entry_guess[k] <= 1.0)
            << where.str();
      // The contact keeps e_d (exact for N_c >= 1.5; at most 1e-5 off at N_c = 1e6).
      const double e = restitution_of(sd);
      ASSERT_TRUE(std::isfinite(e)) << where.str();
      if (c.e_dry > 1e-100) {
        ASSERT_NEAR(std::log(e), std::log(c.e_dry), 1e-3) << where.str();
      }
      const Lubrication &lub = m.lubrication;
      ASSERT_TRUE(std::isfinite(lub.six_pi_mu) && std::isfinite(lub.lambda_saturated) &&
                  std::isfinite(lub.integral_saturated))
          << where.str();
      if (lub.active()) {
        // Film radii for which eps_al lies within [eps_1, 1] (a fixed eps_al does; a grid's
        // 0.75 dx / R does for R >= 0.75 dx).
        const double radius = c.grid_spacing > 0.0 ? 0.75 * c.grid_spacing / d.log_uniform(c.eps_saturation, 1.0)
                                                   : d.log_uniform(1e-100, 1e100);
        const Lubrication::Activation al = lub.activation(FilmRadius(radius));
        ASSERT_TRUE(std::isfinite(al.eps) && std::isfinite(al.lambda) && std::isfinite(al.integral)) << where.str();
        for (double eps : {c.eps_release - 1.0, c.eps_release, 0.0, 0.5 * c.eps_saturation, c.eps_saturation,
                           0.5 * (c.eps_saturation + al.eps), al.eps, 2.0})
          ASSERT_TRUE(std::isfinite(lub.film_integral(eps, al))) << where.str() << " eps " << eps;
        ASSERT_GE(lub.film_integral(0.0, al), 0.0) << where.str();
      }
      calibration_warning(c, partner);    // must not trap
    }
    const TangentialModel tm = make_contact_model(c, Partner::particle, dt).tangential;
    ASSERT_TRUE(std::isfinite(tm.stiffness_step) && tm.stiffness_step > 0.0) << where.str();
    ASSERT_TRUE(std::isfinite(tm.damping_step) && tm.damping_step >= 0.0) << where.str();
    ASSERT_TRUE(std::isfinite(tm.two_pi_mu)) << where.str();
  }
  EXPECT_GE(accepted, 3000);
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
        << "mu " << m.viscosity << " rho " << m.density << " d " << diameter << " w " << slip << " voidage " << voidage
        << " law " << trial % 2 << " hindrance " << (trial / 2) % 3;
  }
}
