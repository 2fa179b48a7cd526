// A sticking oblique impact through the whole contact (contact.h), normal and tangential motion
// integrated as an engine does (leapfrog), swept over the impact phase: the slip of the contact
// point comes back reversed with exactly e_t, dry and in a liquid (whose film shortens the overlap
// by part of a step, so that N_c - 1 or N_c evaluations fall in it), against a wall and between
// two unequal spheres. The line of centres is held fixed (an engine's pair also turns it: tests/
// lammps/test_oblique_phase.py bounds that part). Coulomb never binds (mu_c huge).
#include "lubricated/contact.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {

struct Body {
  double radius = 0.0, mass = 0.0;    // mass 0: a wall
  Vec3 v, omega;
};

struct Impact {
  double beta = 0.0;      // -s' / s0 along the first slip
  int evaluations = 0;    // evaluations in overlap
};

constexpr double speed = 0.5, slip_speed = 0.05;    // normal approach, initial slip [m/s]

// Body i above partner j (or a wall) along n = z, approaching at `speed` from (5 + phase) steps
// of free flight, slipping along x; the normal motion is the relative coordinate (gap, u).
template <Partner PARTNER> Impact impact(const Coefficients &c, Body i, Body j, double phase, double dt, int steps)
{
  constexpr bool wall = PARTNER == Partner::wall;
  const ContactModel m = make_contact_model(c, PARTNER, dt);
  const double m_e = wall ? i.mass : i.mass * j.mass / (i.mass + j.mass);
  const Vec3 n{0.0, 0.0, 1.0};
  double gap = (5.0 + phase) * speed * dt, u = -speed;
  double elongation[3] = {0.0, 0.0, 0.0};
  HistorySlot slot{elongation, false};
  auto point = [&]() {
    ContactPoint p;
    p.gap = gap, p.u_n = u, p.reduced_mass = m_e, p.n = n;
    p.film = wall ? FilmRadius(i.radius) : film_radius_pair(i.radius, j.radius);
    p.dv = {i.v.x - j.v.x, i.v.y - j.v.y, u};
    p.omega_i = i.omega, p.omega_j = j.omega;
    p.radius_i = i.radius, p.radius_j = j.radius;
    p.reduced_radius = wall ? i.radius : i.radius * j.radius / (i.radius + j.radius);
    p.mass_i = i.mass, p.mass_j = j.mass;
    return p;
  };
  auto slip = [&]() {
    const ContactPoint p = point();
    return surface_slip(p.dv, contact_lever(p.omega_i, p.radius_i, p.omega_j, p.radius_j), n);
  };
  const double s0 = slip().x;
  Impact out;
  for (int step = 0; step < steps; ++step) {
    out.evaluations += gap < 0.0;
    const ContactForces f = contact_forces<true, PARTNER>(m, point(), slot);
    u += f.normal.total() * dt / m_e;
    i.v = plus(i.v, scaled(f.tangential, dt / i.mass));
    i.omega = plus(i.omega, scaled(f.torque_i, dt / sphere_inertia(i.mass, i.radius)));
    if (!wall) {
      j.v = minus(j.v, scaled(f.tangential, dt / j.mass));
      j.omega = plus(j.omega, scaled(f.torque_j, dt / sphere_inertia(j.mass, j.radius)));
    }
    gap += u * dt;
  }
  EXPECT_GT(gap, 0.0);
  out.beta = -slip().x / s0;
  return out;
}

Coefficients sticking(double n_contact, bool wet)
{
  Coefficients c;
  c.e_dry = 0.97;
  c.n_contact = n_contact;
  c.friction = 1e9;
  c.e_tangential = wet ? 0.39 : 0.83;
  if (wet) {    // glycerol-water around 3 mm glass spheres (St about 40); no shear film
    c.viscosity = 0.01;
    c.eps_activation = 0.1;
    c.shearfilm = 0;
  }
  return c;
}

// Glass spheres of radius 1.59 mm and 1 mm; t_c = 0.04 R / U of the larger.
const Body larger{1.59e-3, 2500.0 * 4.18879 * 1.59e-3 * 1.59e-3 * 1.59e-3, {slip_speed, 0, 0}, {}};
const Body smaller{1.0e-3, 2500.0 * 4.18879 * 1e-3 * 1e-3 * 1e-3, {}, {0, 0, 0}};
const double contact_time = 0.04 * 1.59e-3 / speed;

template <Partner PARTNER> void sweep(double n_contact, bool wet, int &shorter, int &longer)
{
  const Coefficients c = sticking(n_contact, wet);
  const double dt = contact_time / n_contact;
  const int steps = 5 + static_cast<int>(n_contact) + 4 + (wet ? 200 : 0);
  for (int k = 0; k <= 64; ++k) {
    const double phase = k == 64 ? 1e-9 : (k + 0.5) / 64.0;
    Coefficients ck = c;
    ck.t_contact = contact_time;
    const Impact r = impact<PARTNER>(ck, larger, smaller, phase, dt, steps);
    EXPECT_NEAR(r.beta, c.tangential_restitution(), 1e-9) << "phase " << phase << " N_c " << n_contact;
    shorter += r.evaluations<n_contact, longer += r.evaluations> n_contact;
  }
}

}    // namespace

TEST(ObliqueImpact, StickingWallImpactReturnsEtAtEveryPhase)
{
  int shorter = 0, longer = 0;
  for (double n_contact : {8.0, 5.0})
    for (bool wet : {false, true})
      sweep<Partner::wall>(n_contact, wet, shorter, longer);
  EXPECT_GT(shorter, 0);    // the film's overlap holds N_c - 1 evaluations at some phases
}

TEST(ObliqueImpact, StickingPairImpactReturnsEtAtEveryPhase)
{
  int shorter = 0, longer = 0;
  for (double n_contact : {8.0, 5.0})
    for (bool wet : {false, true})
      sweep<Partner::particle>(n_contact, wet, shorter, longer);
  EXPECT_GT(shorter, 0);
}
