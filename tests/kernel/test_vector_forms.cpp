// The branch-free forms the pair style's vectorised loops use (film_force_apart for pairs that
// stay apart over a step, sustained_contact_force, log_inline), and the one-pair form of
// sustained_contact_force (lambda(eps_al) given): the same forces as normal_force() where they
// apply, to rounding.
#include "lubricated/inline_atan.h"
#include "lubricated/inline_exp.h"
#include "lubricated/inline_log.h"
#include "lubricated/inline_sincos.h"
#include "lubricated/contact.h"
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace lubricated;

namespace {

// Distance of a from b in units in the last place of b.
double ulps(double a, double b)
{
  if (a == b) return 0.0;
  return std::fabs(a - b) / (std::nextafter(std::fabs(b), INFINITY) - std::fabs(b));
}

struct Draw {
  std::mt19937_64 rng;
  explicit Draw(unsigned seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, uniform(0.0, 1.0)); }
};

// A film with a fixed activation or (grid) a grid spacing, over the allowed ranges.
void draw_film(Draw &d, bool grid, Coefficients &c)
{
  c.viscosity = d.log_uniform(1e-6, 10.0);
  c.eps_saturation = d.log_uniform(1e-6, 0.05);
  if (grid)
    c.grid_spacing = d.log_uniform(1e-6, 1e-1);
  else
    c.eps_activation = d.uniform(1.5 * c.eps_saturation, 1.0);
  c.eps_release = d.uniform(-0.1, 0.0);
}

// Two spheres of radii up to 5 apart, their film radius and a reduced mass.
struct DrawnPair {
  FilmRadius radius;
  double mass;
};
DrawnPair draw_pair(Draw &d)
{
  const double ri = d.log_uniform(1e-6, 1e-1), rj = ri * d.log_uniform(0.2, 5.0);
  return {film_radius_pair(ri, rj), d.log_uniform(1e-12, 1.0)};
}

// An exact contact model of trial `trial` (a film on three trials in four, with a grid spacing on
// one in three), at least min_steps steps per contact, and its time step.
struct DrawnModel {
  Coefficients coefficients;
  NormalModel model;
  double dt;
  bool grid;
};
DrawnModel draw_contact_model(Draw &d, int trial, double min_steps)
{
  DrawnModel drawn;
  Coefficients &c = drawn.coefficients;
  c.e_dry = d.log_uniform(1e-3, 1.0);
  c.n_contact = d.log_uniform(min_steps, 64.0);
  drawn.grid = trial % 3 == 0;
  if (trial % 4 != 0) draw_film(d, drawn.grid, c);
  drawn.dt = d.log_uniform(1e-8, 1e-2);
  if (validate(c).empty()) drawn.model = make_normal_model(c, Partner::particle, drawn.dt);
  return drawn;
}

// Every state of every trial: a valid contact model (draw_contact_model), then `states` pairs
// (draw_pair) handed to body(drawn, radius, mass, state), which draws its gap and velocity from d;
// the draws in the order of a loop over trials and states. Stops at a fatal failure.
template <class Body> void for_each_drawn_pair(Draw &d, double min_steps, int states, Body body)
{
  for (int trial = 0; trial < 400; ++trial) {
    const DrawnModel drawn = draw_contact_model(d, trial, min_steps);
    ASSERT_EQ(validate(drawn.coefficients), "");
    for (int state = 0; state < states; ++state) {
      const auto [radius, mass] = draw_pair(d);
      body(drawn, radius, mass, state);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

// normal_force takes the film over a step as a difference of film integrals P, sums of terms
// of order 1: its rounding is about 1e-16 of those terms (as a force), however close the two
// ends of the step; the forms here differ from it by that and by the inline logarithm.
double film_rounding(const NormalModel &m, const FilmRadius &radius, double dt)
{
  const Lubrication &lub = m.lubrication;
  const Lubrication::Activation al = lub.activation(radius);
  const double terms = std::fabs(al.integral) + std::fabs(lub.integral_saturated) +
                       (std::fabs(al.lambda) + std::fabs(lub.lambda_saturated)) * (al.eps + 0.1);
  return 1e-13 * lub.six_pi_mu * radius.value * radius.value * terms / dt;
}

// A drawn wet particle model (draw_film: a grid or a fixed activation) and its time step.
std::pair<NormalModel, double> draw_film_model(Draw &d, bool grid)
{
  Coefficients c;
  c.e_dry = 0.9;
  draw_film(d, grid, c);
  EXPECT_EQ(validate(c), "");
  const double dt = d.log_uniform(1e-8, 1e-3);
  return {make_normal_model(c, Partner::particle, dt), dt};
}

}    // namespace

TEST(InlineLog, WithinFourUlpsOfTheLibraryOverTheNormalRange)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-708.0, 709.0), near_one(-1e-3, 1e-3);
  double worst = 0.0;
  for (int n = 0; n < 200000; ++n) {
    const double x = n % 4 == 0 ? 1.0 + near_one(rng) : std::exp(exponent(rng));
    // Close to 1 the logarithm is small: count its error against the size of x - 1 instead.
    const double reference = std::log(x);
    const double error = std::fabs(x - 1.0) < 0.5
                             ? std::fabs(log_inline(x) - reference) / std::fabs(x - 1.0) / 2.220446049250313e-16
                             : ulps(log_inline(x), reference);
    worst = std::max(worst, error);
  }
  EXPECT_LE(worst, 4.0);
  EXPECT_EQ(log_inline(1.0), 0.0);
  for (int k = -1022; k <= 1023; k += 89)
    EXPECT_LE(ulps(log_inline(std::ldexp(1.0, k)), k * std::log(2.0)), 1.0) << "2^" << k;
}

// The two- and three-argument forms (one division over a common denominator): each logarithm
// within a few more ulps of the library's than log_inline alone, whatever the other arguments.
TEST(InlineLog, SharedDivisionWithinEightUlps)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> exponent(-708.0, 709.0), near_one(-1e-3, 1e-3);
  auto draw = [&](int n) { return n % 3 == 0 ? 1.0 + near_one(rng) : std::exp(exponent(rng)); };
  auto error = [](double got, double x) {
    const double reference = std::log(x);
    return std::fabs(x - 1.0) < 0.5 ? std::fabs(got - reference) / std::fabs(x - 1.0) / 2.220446049250313e-16
                                    : ulps(got, reference);
  };
  double worst = 0.0;
  for (int n = 0; n < 100000; ++n) {
    const double a = draw(n), b = draw(n + 1), c = draw(n + 2);
    double la, lb, lc, la2, lb2;
    log_inline(a, b, c, la, lb, lc);
    log_inline(a, b, la2, lb2);
    worst = std::max({worst, error(la, a), error(lb, b), error(lc, c), error(la2, a), error(lb2, b)});
  }
  EXPECT_LE(worst, 8.0);
  double l1, l2, l3;
  log_inline(1.0, 1.0, 1.0, l1, l2, l3);
  EXPECT_EQ(l1, 0.0);
  EXPECT_EQ(l3, 0.0);
}

// Random wet, exactly integrated pairs, apart over the step (gap >= 0 and gap - u_n dt >= 0,
// from inside the saturated film to past eps_al): the film-only force equals normal_force's
// film (and normal_force has no contact part there), within film_rounding.
TEST(FilmApart, EqualsTheFilmOfNormalForce)
{
  Draw d(2026);
  int compared = 0, in_film = 0, clamped = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Coefficients c;
    c.e_dry = d.log_uniform(1e-3, 1.0);
    const bool grid = trial % 3 == 0;
    draw_film(d, grid, c);
    if (trial % 4 == 0) c.eps_release = 0.0, c.legendre = 35.0;
    ASSERT_EQ(validate(c), "");
    const double dt = d.log_uniform(1e-8, 1e-2);
    const NormalModel m = make_normal_model(c, Partner::particle, dt);
    for (int state = 0; state < 100; ++state) {
      const auto [radius, mass] = draw_pair(d);
      const double eps_al = m.lubrication.activation_for(radius);
      const double gap = radius.value * d.log_uniform(1e-3 * c.eps_saturation, 2.0 * eps_al);
      // |u_n| dt from a creeping fraction of the gap up to the whole gap (closing) or beyond.
      const double u_n = gap / dt * d.log_uniform(1e-9, 1.0) * (state % 2 ? 1.0 : -1.0);
      const NormalForce expected = normal_force(m, gap, radius, mass, u_n);
      ASSERT_EQ(expected.contact, 0.0);
      const double film = grid ? film_force_apart<true>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt)
                               : film_force_apart<false>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt);
      ASSERT_NEAR(film, expected.lubrication, film_rounding(m, radius, dt))
          << "eps " << gap / radius.value << " eps_al " << eps_al << " u_n dt / gap " << u_n * dt / gap;
      if (gap < eps_al * radius.value) ++in_film;
      if (std::fabs(expected.lubrication) * dt >= mass * std::fabs(u_n) * (1.0 - 1e-12)) ++clamped;
      // Beyond eps_al before and after the step the film is exactly zero.
      if (gap - u_n * dt >= eps_al * radius.value && gap >= eps_al * radius.value) {
        ASSERT_EQ(film, 0.0);
      }
      ++compared;
    }
  }
  // The draws reach the film, its saturated part and the cap on the impulse.
  EXPECT_EQ(compared, 40000);
  EXPECT_GT(in_film, 10000);
  EXPECT_GT(clamped, 100);
}

// Random exactly integrated pairs, dry and wet, in overlap now and a step ago: where
// sustained_contact_force says the contact is sustained, contact and energy equal
// normal_force's and the film does within film_rounding (both ends saturated).
TEST(SustainedContact, EqualsNormalForceWhereItApplies)
{
  Draw d(11);
  int sustained_count = 0, other_count = 0;
  for_each_drawn_pair(d, 1.0, 100, [&](const DrawnModel &drawn, const FilmRadius &radius, double mass, int state) {
    const NormalModel &m = drawn.model;
    const double dt = drawn.dt;
    const bool grid = drawn.grid;
    const double gap = -radius.value * d.log_uniform(1e-9, 0.2);
    // Overlap rates from creeping to leaving the overlap within the step, both signs.
    const double u_n = -gap / dt * d.log_uniform(1e-6, 3.0) * (state % 2 ? 1.0 : -1.0);
    bool sustained = false;
    const NormalForce vector_form = grid ? sustained_contact_force<true>(m, gap, radius, mass, u_n, sustained)
                                         : sustained_contact_force<false>(m, gap, radius, mass, u_n, sustained);
    if (!sustained) {
      ++other_count;
      return;
    }
    ++sustained_count;
    const NormalForce expected = normal_force(m, gap, radius, mass, u_n);
    ASSERT_DOUBLE_EQ(vector_form.contact, expected.contact);
    ASSERT_DOUBLE_EQ(vector_form.energy, expected.energy);
    ASSERT_NEAR(vector_form.lubrication, expected.lubrication, film_rounding(m, radius, dt))
        << "gap " << gap << " u_n dt " << u_n * dt;
    // The one-pair form (LIGGGHTS's contacts): lambda(eps_al) by std::log, as activation()
    // but 1 / eps_al as R / (0.75 dx): to the rounding of lambda's terms.
    const Lubrication &lub = m.lubrication;
    const Lubrication::Activation al = lub.activation(radius);
    const double l = std::log(std::max(al.eps, 1e-300)),
                 terms = std::fabs(lub.expansion.c_inv / al.eps) + std::fabs(lub.expansion.c_log * l) +
                         std::fabs(lub.expansion.c_elog * al.eps * l) + std::fabs(lub.expansion.c_0);
    if (lub.grid_spacing > 0.0)
      ASSERT_NEAR(lub.lambda_activation_for(radius), al.lambda, 1e-15 * terms);
    else    // the type pair's own lambda(eps_al)
      ASSERT_EQ(lub.lambda_activation_for(radius), al.lambda);
    bool scalar_sustained = false;
    const NormalForce scalar_form = sustained_contact_force(
        m, gap, radius, mass, u_n, m.lubrication.lambda_activation_for(radius), scalar_sustained);
    ASSERT_TRUE(scalar_sustained);
    ASSERT_DOUBLE_EQ(scalar_form.contact, expected.contact);
    ASSERT_NEAR(scalar_form.lubrication, expected.lubrication, film_rounding(m, radius, dt));
  });
  // Both kinds are drawn: sustained contacts and contacts that start or end within the step.
  EXPECT_GT(sustained_count, 10000);
  EXPECT_GT(other_count, 5000);
}

TEST(InlineExp, OneMinusExpWithinTwoUlpsOfExpm1)
{
  EXPECT_EQ(one_minus_exp_neg_inline(0.0), 0.0);
  EXPECT_EQ(one_minus_exp_neg_inline(1e300), 1.0);
  for (double x = 1e-14; x < 800.0; x *= 1.001)
    EXPECT_LE(ulps(one_minus_exp_neg_inline(x), -std::expm1(-x)), 2.0) << x;
}

TEST(InlineExp, ExpWithinTwoUlpsOfTheLibrary)
{
  EXPECT_EQ(exp_inline(0.0), 1.0);
  for (double x = -708.0; x < 709.0; x += 0.0137)
    EXPECT_LE(ulps(exp_inline(x), std::exp(x)), 2.0) << x;
}

// Over the angles an exit can take (y > 0, x of either sign) and scales from 1e-300 to 1e300.
TEST(InlineAtan, Atan2WithinFourUlpsOfTheLibrary)
{
  Draw d(5);
  double worst = 0.0;
  for (int n = 0; n < 200000; ++n) {
    const double scale = d.log_uniform(1e-300, 1e300);
    const double y = scale * d.uniform(0.0, 1.0), x = scale * d.uniform(-1.0, 1.0);
    if (y == 0.0 && x == 0.0) continue;
    worst = std::max(worst, ulps(atan2_nonnegative_inline(y, x), std::atan2(y, x)));
  }
  EXPECT_LE(worst, 4.0);
  EXPECT_EQ(atan2_nonnegative_inline(0.0, 1.0), 0.0);
  EXPECT_LE(ulps(atan2_nonnegative_inline(1.0, 0.0), std::atan2(1.0, 0.0)), 1.0);
  EXPECT_LE(ulps(atan2_nonnegative_inline(0.0, -1.0), std::atan2(0.0, -1.0)), 1.0);
}

// Contacts in overlap now and a step ago that leave it within the coming step (the vectorised
// contact loop's exits): normal_force()'s exit from the oscillator and free flight, to the
// rounding of its (g2 - 2 g1 + g0) / dt^2 (the inline atan2 and exp within a few ulps); the
// saturated film and the energy as sustained contacts.
TEST(ContactExit, EqualsNormalForceWhereItApplies)
{
  Draw d(13);
  int exits = 0;
  for_each_drawn_pair(d, 1.6, 100, [&](const DrawnModel &drawn, const FilmRadius &radius, double mass, int) {
    const NormalModel &m = drawn.model;
    const double dt = drawn.dt;
    const bool grid = drawn.grid;
    const double gap = -radius.value * d.log_uniform(1e-9, 0.2);
    // Separating: from creeping to leaving the overlap within the step.
    const double u_n = -gap / dt * d.log_uniform(1e-3, 3.0);
    const double g0 = gap - u_n * dt;
    if (!leaves_overlap(m.step, gap, g0)) return;
    ++exits;
    const NormalForce vector_form = grid ? overlap_exit_force<true>(m, gap, radius, mass, u_n)
                                         : overlap_exit_force<false>(m, gap, radius, mass, u_n);
    const NormalForce expected = normal_force(m, gap, radius, mass, u_n);
    const double terms = mass * (std::fabs(g0) + 2.0 * std::fabs(gap) + std::fabs(u_n) * dt) / (dt * dt);
    ASSERT_NEAR(vector_form.contact, expected.contact, 1e-13 * terms) << "gap " << gap << " u_n dt " << u_n * dt;
    ASSERT_DOUBLE_EQ(vector_form.energy, expected.energy);
    ASSERT_NEAR(vector_form.lubrication, expected.lubrication, film_rounding(m, radius, dt));
  });
  EXPECT_GT(exits, 2000);
}

// Over an oscillator's angles in a step (0 to pi) and beyond, both signs, down to 1e-12.
TEST(InlineSincos, WithinTwoUlpsOfTheLibrary)
{
  double s = 1.0, c = 0.0;
  sincos_inline(0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
  for (double x = 1e-12; x < 1e5; x *= 1.0003)
    for (const double y : {x, -x}) {
      sincos_inline(y, s, c);
      ASSERT_LE(ulps(s, std::sin(y)), 2.0) << y;
      ASSERT_LE(ulps(c, std::cos(y)), 2.0) << y;
    }
}

// Pairs apart now or a step ago within a step of contact (the vectorised loop of the steps where
// a contact starts or ends), and in overlap at both (sustained, or leaving the overlap):
// normal_force()'s entry, exit, root finding and recurrence. Its Newton step is
// falling_root's first, from the same table (the share r / (1 + r) rounded differently), with
// exp, sin and cos within 2 ulps: the acceleration within 1e-12 of its terms (g0, g1, the
// landing gap and u dt, over dt^2) and the film's rounding, which its kick carries; the film and
// the energy as film_force_apart's. Where the
// step misses the tolerance the pair is left to normal_force() (resolved = false): 5 % of the
// roots drawn here, none of the 1.1e6 in the 2000-sphere bench beds.
TEST(ContactEvent, EqualsNormalForceWhereItApplies)
{
  Draw d(17);
  int kinds[4] = {0, 0, 0, 0}, unresolved = 0;
  for_each_drawn_pair(d, 1.6, 150, [&](const DrawnModel &drawn, const FilmRadius &radius, double mass, int state) {
    const NormalModel &m = drawn.model;
    ASSERT_FALSE(m.calibrated());
    const double dt = drawn.dt;
    const bool grid = drawn.grid, wet = m.lubrication.active();
    // Gaps and steps of either sign: approaching, just entered, just left, in overlap at both.
    const int kind = state % 4;
    const double g1 = radius.value * d.log_uniform(1e-9, 0.2) * (kind == 1 || kind == 3 ? -1.0 : 1.0);
    const double g0 = radius.value * d.log_uniform(1e-9, 0.2) * (kind >= 2 ? -1.0 : 1.0);
    const double u_n = (g1 - g0) / dt;
    if (!contact_possible(g1, u_n, dt)) return;
    bool resolved = false;
    NormalForce vector_form;
    if (!wet)
      vector_form = contact_event_force<false, false>(m, g1, radius, mass, u_n, resolved);
    else if (grid)
      vector_form = contact_event_force<true, true>(m, g1, radius, mass, u_n, resolved);
    else
      vector_form = contact_event_force<true, false>(m, g1, radius, mass, u_n, resolved);
    if (!resolved) {
      ASSERT_TRUE(kind == 1 || kind == 2);    // only entries and exits have roots to find
      ++unresolved;
      return;
    }
    ++kinds[kind];
    const NormalForce expected = normal_force(m, g1, radius, mass, u_n);
    const double landing = expected.contact / mass * dt * dt + 2.0 * g1 - g0;
    const double terms =
        mass * (std::fabs(g0) + 2.0 * std::fabs(g1) + std::fabs(landing) + std::fabs(u_n) * dt) / (dt * dt);
    // The film's rounding enters the contact through its kick (-kick / dt and the stop).
    const double film = wet ? film_rounding(m, radius, dt) : 0.0;
    ASSERT_NEAR(vector_form.contact, expected.contact, 1e-12 * terms + 2.0 * film)
        << "kind " << kind << " g1 " << g1 << " g0 " << g0 << " dt " << dt;
    ASSERT_DOUBLE_EQ(vector_form.energy, expected.energy);
    ASSERT_NEAR(vector_form.lubrication, expected.lubrication, film);
  });
  for (const int count : kinds)
    EXPECT_GT(count, 5000);
  EXPECT_LT(unresolved, (kinds[1] + kinds[2]) / 8) << kinds[1] << " " << kinds[2];
}

// The shear film of the vectorised film loop against shear_film_force(), over gaps in and out of
// the film, masses over 12 decades (the step's decay from 1e-12 to 1e6) and a zero mass.
TEST(ShearFilmApart, EqualsTheShearFilmForce)
{
  Draw draw(11);
  for (int k = 0; k < 20000; k++) {
    Coefficients c;
    c.e_dry = 0.9, c.n_contact = 8, c.friction = 0.3;
    c.viscosity = draw.log_uniform(1e-4, 10.0);
    c.eps_activation = draw.uniform(0.01, 1.0);
    const double dt = 1e-5;
    const TangentialModel m = make_contact_model(c, Partner::particle, dt).tangential;
    ASSERT_TRUE(m.film_active());
    const double eps1 = 1e-3, eps2 = -1e-2, radius = 1e-3;
    const double eps = draw.uniform(0.0, 1.2);
    const double m_t = k % 100 == 0 ? 0.0 : draw.log_uniform(1e-14, 1e-2);
    const Vec3 s{1.0, -2.0, 0.5};
    const double damping = shear_film_damping_apart(m, eps, c.eps_activation, eps1, eps2, radius, m_t);
    if (m_t == 0.0) {
      EXPECT_EQ(damping, 0.0);
      continue;
    }
    const Vec3 f = shear_film_force(m, s, eps, c.eps_activation, eps1, eps2, radius, m_t);
    EXPECT_NEAR(-damping * s.x, f.x, 1e-12 * std::fabs(f.x) + 1e-300) << eps << " " << m_t;
    EXPECT_NEAR(-damping * s.y, f.y, 1e-12 * std::fabs(f.y) + 1e-300);
  }
}

// The shear film's logarithm that the normal film's logarithms give (film_force_apart's
// shear_log) against std::log(eps_al / max(eps, eps_1)) inside the film (eps_2 < eps < eps_al),
// over fixed and grid activations, both signs of the gap and motion: within the rounding of a
// difference of two log_inline results (each 8 ulps of its size, InlineLog.SharedDivision) and
// of std::log's argument, so that the shear film's coefficient is that of shear_film_force()
// to 1e-15 of 2 pi mu R_e |ln eps_1|.
TEST(ShearFilmApart, TheNormalFilmsLogarithmIsTheShearFilms)
{
  Draw d(29);
  int inside = 0, saturated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const bool grid = trial % 2 == 0;
    const auto [m, dt] = draw_film_model(d, grid);
    for (int state = 0; state < 100; ++state) {
      const auto [radius, mass] = draw_pair(d);
      const double eps_al = m.lubrication.activation_for(radius);
      const double eps1 = m.lubrication.eps_saturation;
      // Inside the film: from just above eps_2 (in overlap, saturated) to eps_al.
      const double eps =
          state % 4 == 0 ? d.uniform(0.9 * m.lubrication.eps_release, eps1) : eps1 * d.log_uniform(1.0, eps_al / eps1);
      if (!(eps < eps_al && eps > m.lubrication.eps_release)) continue;
      const double gap = eps * radius.value;
      const double u_n = radius.value / dt * d.uniform(-0.5, 0.5) * eps_al;
      double shear_log = NAN;
      if (grid)
        film_force_apart<true>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt, shear_log);
      else
        film_force_apart<false>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt, shear_log);
      const double eps_used = gap * radius.inverse;
      const double expected = std::log(eps_al / std::max(eps_used, eps1));
      const double eps_machine = std::numeric_limits<double>::epsilon();
      const double bound =
          8.0 * eps_machine * (std::fabs(std::log(eps_al)) + std::fabs(std::log(std::max(eps_used, eps1)))) +
          2.0 * eps_machine * std::fabs(expected);
      ASSERT_NEAR(shear_log, expected, bound) << "eps " << eps_used << " eps_al " << eps_al;
      ++(eps_used < eps1 ? saturated : inside);
    }
  }
  EXPECT_GT(inside, 15000);
  EXPECT_GT(saturated, 5000);
}

// The film apart's lambda(eps_al), which the vectorised contact loops hand to the sustained
// contact's saturated film instead of a logarithm of their own, is the activation's (std::log) to
// rounding: a few ulps of each term of lambda = c_inv / eps + c_log l + c_elog eps l + c_0.
TEST(FilmApart, ItsLambdaOfActivationIsTheActivations)
{
  Draw d(31);
  for (int trial = 0; trial < 300; ++trial) {
    const bool grid = trial % 2 == 0;
    const auto [m, dt] = draw_film_model(d, grid);
    const Expansion &e = m.lubrication.expansion;
    for (int state = 0; state < 30; ++state) {
      const auto [radius, mass] = draw_pair(d);
      const Lubrication::Activation al = m.lubrication.activation(radius);
      const double gap = d.uniform(-0.01, 1.5) * al.eps * radius.value;
      const double u_n = radius.value / dt * d.uniform(-0.5, 0.5) * al.eps;
      double shear_log, lambda_al = NAN;
      if (grid)
        film_force_apart<true>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt, shear_log, lambda_al);
      else
        film_force_apart<false>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt, shear_log, lambda_al);
      const double l = std::log(al.eps);
      const double terms =
          std::fabs(e.c_inv / al.eps) + std::fabs(e.c_log * l) + std::fabs(e.c_elog * al.eps * l) + std::fabs(e.c_0);
      ASSERT_NEAR(lambda_al, al.lambda, 8.0 * std::numeric_limits<double>::epsilon() * terms)
          << "eps_al " << al.eps << (grid ? " grid" : " fixed");
    }
  }
}
