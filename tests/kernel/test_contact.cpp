// The whole contact (contact.h) driving real rigid-body dynamics: forces on both spheres and
// torques on both, integrated as an engine does (leapfrog: forces from the velocities of the
// last step, then the velocities updated). What the parts' own tests (test_tangential.cpp)
// cannot see: lever arms, signs and the tangential mass 2/7 m_e that the torques must produce.
#include "lubricated/contact.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {

// A sphere's state in the plane of the contact; positions stay fixed (the normal gap is held,
// so the contact force is steady and only the tangential motion evolves).
struct Sphere {
  double radius, mass;
  Vec3 v, omega;
  double inertia() const { return sphere_inertia(mass, radius); }
};

constexpr double dt = 1e-6;
const Vec3 z_axis{0.0, 0.0, 1.0};    // n: from j (or the wall) below to i above

Coefficients frictional(double mu, double e_t)
{
  Coefficients c;
  c.e_dry = 0.8;
  c.n_contact = 8;
  c.friction = mu;
  c.e_tangential = e_t;
  return c;
}

ContactPoint pair_point(const Sphere &i, const Sphere &j, double gap)
{
  ContactPoint p;
  p.gap = gap;
  p.u_n = 0.0;
  p.reduced_mass = reduced_mass(i.mass, j.mass);
  p.film = film_radius_pair(i.radius, j.radius);
  p.n = z_axis;
  p.dv = minus(i.v, j.v);
  p.omega_i = i.omega, p.omega_j = j.omega;
  p.radius_i = i.radius, p.radius_j = j.radius;
  p.reduced_radius = i.radius * j.radius / (i.radius + j.radius);
  p.mass_i = i.mass, p.mass_j = j.mass;
  return p;
}

ContactPoint wall_point(const Sphere &i, double gap)
{
  ContactPoint p;
  p.gap = gap;
  p.u_n = 0.0;
  p.reduced_mass = i.mass;
  p.film = FilmRadius(i.radius);
  p.n = z_axis;
  p.dv = i.v;
  p.omega_i = i.omega;
  p.radius_i = i.radius;
  p.reduced_radius = i.radius;
  p.mass_i = i.mass;
  return p;
}

// One leapfrog kick of the tangential force and both torques (the normal force is held by the
// fixed gap and left out).
void kick(Sphere &i, Sphere *j, const ContactForces &c)
{
  i.v = plus(i.v, scaled(c.tangential, dt / i.mass));
  i.omega = plus(i.omega, scaled(c.torque_i, dt / i.inertia()));
  if (!j) return;
  j->v = minus(j->v, scaled(c.tangential, dt / j->mass));
  j->omega = plus(j->omega, scaled(c.torque_j, dt / j->inertia()));
}

Vec3 slip(const ContactPoint &p)
{
  return tangential_part(minus(p.dv, cross(plus(scaled(p.omega_i, p.radius_i), scaled(p.omega_j, p.radius_j)), p.n)),
                         p.n);
}

// Angular momentum about the contact point (the surfaces meet between the centres): every
// contact force acts there and the rolling torques cancel, so it is conserved step by step.
Vec3 angular_momentum(const Sphere &i, const Sphere *j)
{
  Vec3 l = plus(cross(scaled(z_axis, i.radius), scaled(i.v, i.mass)), scaled(i.omega, i.inertia()));
  if (j) l = plus(l, plus(cross(scaled(z_axis, -j->radius), scaled(j->v, j->mass)), scaled(j->omega, j->inertia())));
  return l;
}

double norm(const Vec3 &a)
{
  return std::sqrt(dot(a, a));
}

}    // namespace

// Two unequal spheres stuck together by friction, set slipping by their spins and velocities:
// their tangential motion is the oscillator of mass 2/7 m_e only if the torques act with the
// right lever arms on the spheres' own inertia; then the slip comes back as -e_t s0 after
// exactly t_c (N_c steps in overlap from an entry on a step boundary, then the step apart that
// releases the spring), whatever splits it between translation and rotation.
TEST(WholeContact, StuckPairReversesItsSlipWithEtThroughForcesAndTorques)
{
  for (double e_t : {0.9, 0.5, 0.1}) {
    const ContactModel m = make_contact_model(frictional(1e9, e_t), Partner::particle, dt);
    Sphere i{1.0e-3, 1.05e-5, {0.01, -0.004, 0.0}, {3.0, 5.0, -2.0}};
    Sphere j{0.6e-3, 3.6e-6, {-0.002, 0.003, 0.0}, {-4.0, 1.0, 7.0}};
    double elongation[3] = {0.0, 0.0, 0.0};
    HistorySlot history{elongation, false};
    const double gap = -1e-3 * i.radius;
    const Vec3 s0 = slip(pair_point(i, j, gap));
    const Vec3 l0 = angular_momentum(i, &j);
    for (int step = 0; step < 8; ++step) {
      const ContactPoint p = pair_point(i, j, gap);
      kick(i, &j, contact_forces<true>(m, p, history));
      // Conserved to rounding at every step (relative to the spins' share).
      const Vec3 dl = minus(angular_momentum(i, &j), l0);
      EXPECT_LT(norm(dl), 1e-13 * norm(l0)) << "e_t " << e_t << " step " << step;
    }
    EXPECT_TRUE(history.touched);
    ContactPoint apart = pair_point(i, j, -gap);    // the overlap ended half a step ago
    apart.u_n = (apart.gap - gap) / dt;
    kick(i, &j, contact_forces<true>(m, apart, history));
    EXPECT_LT(norm(minus(angular_momentum(i, &j), l0)), 1e-13 * norm(l0)) << "e_t " << e_t << " release";
    const Vec3 s = slip(pair_point(i, j, gap));
    EXPECT_FALSE(history.touched);
    EXPECT_NEAR(s.x, -e_t * s0.x, 1e-10 * norm(s0)) << e_t;
    EXPECT_NEAR(s.y, -e_t * s0.y, 1e-10 * norm(s0)) << e_t;
    EXPECT_NEAR(s.z, 0.0, 1e-12 * norm(s0));
  }
}

// Rolling resistance between two spheres rolling on each other (no friction): equal and opposite
// torques (angular momentum conserved), which slow the relative rolling at the rate
// mu_r R_e |F_n| / I_e and stop it without reversing it (1/I_e = 1/I_i + 1/I_j).
TEST(WholeContact, RollingResistanceStopsTheRelativeRollingWithoutReversingIt)
{
  Coefficients c = frictional(0.0, -1.0);
  c.rolling_friction = 0.05;
  const ContactModel m = make_contact_model(c, Partner::particle, dt);
  Sphere i{1.0e-3, 1.05e-5, {0.0, 0.0, 0.0}, {30.0, -20.0, 5.0}};
  Sphere j{0.6e-3, 3.6e-6, {0.0, 0.0, 0.0}, {-10.0, 15.0, -5.0}};
  HistorySlot none;
  const double gap = -1e-3 * i.radius;
  auto rolling_rate = [&]() { return tangential_part(minus(i.omega, j.omega), z_axis); };
  const Vec3 w0 = rolling_rate(), l0 = angular_momentum(i, &j);
  const double inertia = i.inertia() * j.inertia() / (i.inertia() + j.inertia());
  const double torque = 0.05 * i.radius * j.radius / (i.radius + j.radius) *
                        contact_forces<false>(m, pair_point(i, j, gap), none).normal.contact;
  const int steps = static_cast<int>(std::ceil(norm(w0) * inertia / (torque * dt)));    // to stop it
  for (int step = 0; step <= steps + 5; ++step) {
    const Vec3 before = rolling_rate();
    const ContactForces f = contact_forces<true>(m, pair_point(i, j, gap), none);
    EXPECT_EQ(norm(f.tangential), 0.0);
    kick(i, &j, f);
    const Vec3 after = rolling_rate();
    EXPECT_GE(dot(after, w0), 0.0) << step;
    if (step < steps - 1) {    // the full torque: the rate falls by torque dt / I_e
      EXPECT_NEAR(norm(before) - norm(after), torque * dt / inertia, 1e-9 * torque * dt / inertia) << step;
    }
    EXPECT_LT(norm(minus(angular_momentum(i, &j), l0)), 1e-13 * norm(l0)) << step;
  }
  EXPECT_LT(norm(rolling_rate()), 1e-12 * norm(w0));
}

// A sphere launched sliding without spin on a wall: Coulomb friction slows the slip until it
// sticks, the tangential spring's oscillation dies with e_t per t_c, and the sphere rolls at
// 5/7 of its launch speed (angular momentum about the contact point is conserved: m v R + I w
// with I = 2/5 m R^2 and v = w R at the end). Rolling resistance then slows the roll, not the
// slip: with it off the final speed is exact.
TEST(WholeContact, SphereSlidingOnAWallEndsRollingAtFiveSeventhsOfItsSpeed)
{
  const ContactModel m = make_contact_model(frictional(0.3, 0.3), Partner::wall, dt);
  Sphere i{1.0e-3, 1.05e-5, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  const double v0 = 0.005 * i.radius / m.normal.step.contact_time;    // sticks within one t_c
  i.v = {v0 * 0.6, v0 * 0.8, 0.0};
  double history_values[4] = {0.0, 0.0, 0.0, 0.0};
  HistorySlot history{history_values, false};
  const double gap = -1e-3 * i.radius;
  const Vec3 l0 = angular_momentum(i, nullptr);
  bool slid = false;
  for (int step = 0; step < 8 * 60; ++step) {
    const ContactForces c = contact_forces<true, Partner::wall>(m, wall_point(i, gap), history);
    // The Coulomb limit holds and is reached at the start (the sphere slides).
    EXPECT_LE(norm(c.tangential), 0.3 * c.normal.contact * (1.0 + 1e-12));
    slid = slid || norm(c.tangential) >= 0.3 * c.normal.contact * (1.0 - 1e-12);
    kick(i, nullptr, c);
    EXPECT_LT(norm(minus(angular_momentum(i, nullptr), l0)), 1e-13 * norm(l0));
  }
  EXPECT_TRUE(slid);
  EXPECT_LT(norm(slip(wall_point(i, gap))), 1e-9 * v0);
  EXPECT_NEAR(i.v.x, 5.0 / 7.0 * 0.6 * v0, 1e-9 * v0);
  EXPECT_NEAR(i.v.y, 5.0 / 7.0 * 0.8 * v0, 1e-9 * v0);
  // Rolling without slip, v = R omega x n: omega = n x v / R.
  const Vec3 rolling = scaled(cross(z_axis, i.v), 1.0 / i.radius);
  EXPECT_NEAR(i.omega.x, rolling.x, 1e-9 * v0 / i.radius);
  EXPECT_NEAR(i.omega.y, rolling.y, 1e-9 * v0 / i.radius);
}

// The shear film of a sphere gliding and spinning along a wall, in the film (no solid contact):
// its force at the contact point and its torque change the slip at the rate F / m_t, and the
// damper is integrated exactly, so one step multiplies the slip by exp(-C dt / m_t),
// C = 2 pi mu R ln(eps_al / eps) (tangential.h), however viscous the fluid: never reversed.
TEST(WholeContact, ShearFilmDecaysTheSlipExactlyAndNeverReversesIt)
{
  for (double mu : {1e-3, 1.0, 1e3}) {
    Coefficients c = frictional(0.0, -1.0);
    c.viscosity = mu;
    c.eps_activation = 0.1;
    c.shearfilm = 1;
    const ContactModel m = make_contact_model(c, Partner::wall, dt);
    ASSERT_TRUE(m.tangential.film_active());
    Sphere i{1.0e-3, 1.05e-5, {0.02, -0.01, 0.0}, {40.0, 10.0, 3.0}};
    const double eps = 0.01, gap = eps * i.radius;
    HistorySlot none;
    const ContactPoint before = wall_point(i, gap);
    const Vec3 s0 = slip(before);
    kick(i, nullptr, contact_forces<true, Partner::wall>(m, before, none));
    const Vec3 s1 = slip(wall_point(i, gap));
    const double m_t = tangential_mass_ratio * i.mass;
    const double coefficient = 2.0 * pi * mu * i.radius * std::log(0.1 / eps);
    const double factor = std::exp(-coefficient * dt / m_t);
    EXPECT_NEAR(s1.x, factor * s0.x, 1e-12 * norm(s0)) << mu;
    EXPECT_NEAR(s1.y, factor * s0.y, 1e-12 * norm(s0)) << mu;
    EXPECT_GE(dot(s1, s0), 0.0) << mu;
  }
}

// The same contact, whole or split: the normal part is normal_force()'s; with shear_apart the
// shear film comes apart from the rest, adding up to the whole; the wall specialisation equals
// a partner of zero radius that neither moves nor turns.
TEST(WholeContact, PartsAddUpAndTheWallIsAPartnerThatDoesNotTurn)
{
  Coefficients c = frictional(0.4, 0.6);
  c.viscosity = 2e-3;
  c.eps_activation = 0.1;
  c.rolling_friction = 0.05;
  const Sphere i{1.0e-3, 1.05e-5, {0.02, -0.01, -0.003}, {40.0, 10.0, 3.0}};
  for (double eps : {-0.003, -0.0002, 0.0005, 0.05}) {
    const ContactModel wall = make_contact_model(c, Partner::wall, dt);
    ContactPoint p = wall_point(i, eps * i.radius);
    p.u_n = -0.003;
    double h1[3] = {1e-9, -2e-9, 0.0}, h2[3] = {1e-9, -2e-9, 0.0}, h3[3] = {1e-9, -2e-9, 0.0};
    HistorySlot a{h1, true}, b{h2, true}, d{h3, true};
    const ContactForces whole = contact_forces<true, Partner::wall>(wall, p, a);
    const ContactForces apart = contact_forces<true, Partner::wall>(wall, p, b, Evaluation::step, true);
    const ContactForces general = contact_forces<true, Partner::particle>(wall, p, d);
    const NormalForce normal = normal_force(wall.normal, p.gap, p.film, p.reduced_mass, p.u_n);
    HistorySlot unused;
    const ContactForces normal_only = contact_forces<false>(wall, p, unused);
    for (const ContactForces *f : {&whole, &apart, &general, &normal_only}) {
      EXPECT_EQ(f->normal.contact, normal.contact);
      EXPECT_EQ(f->normal.lubrication, normal.lubrication);
      EXPECT_EQ(f->normal.energy, normal.energy);
    }
    const double scale = norm(whole.tangential) + 1e-300, torque_scale = norm(whole.torque_i) + 1e-300;
    EXPECT_LT(norm(minus(plus(apart.tangential, apart.shear), whole.tangential)), 1e-15 * scale) << eps;
    EXPECT_LT(norm(minus(plus(apart.torque_i, apart.shear_torque_i), whole.torque_i)), 1e-15 * torque_scale) << eps;
    EXPECT_LT(norm(minus(general.tangential, whole.tangential)), 1e-15 * scale) << eps;
    EXPECT_LT(norm(minus(general.torque_i, whole.torque_i)), 1e-15 * torque_scale) << eps;
    EXPECT_EQ(h1[0], h3[0]);
    EXPECT_EQ(h1[1], h3[1]);
    EXPECT_EQ(a.touched, d.touched);
    // Out of overlap the elongation is forgotten; in it kept.
    EXPECT_EQ(a.touched, eps < 0.0) << eps;
    if (eps >= 0.0) {
      EXPECT_EQ(h1[0], 0.0);
    }
    // Where the shear film acts (eps_2 < eps < eps_al) it is part of the whole.
    EXPECT_EQ(norm(whole.shear) > 0.0, eps > -0.01 && eps < 0.1) << eps;
  }
}
