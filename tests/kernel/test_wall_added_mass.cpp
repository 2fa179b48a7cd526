// Near-wall added mass of the drag fix (src/lubricated/wall_added_mass.h, doc/fix_fluid_drag.rst
// keyword wall).
#include "lubricated/wall_added_mass.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

TEST(WallAddedMass, FirstReflectionValues)
{
  const AddedMassWall floor{2, 0.0};
  const double radius = 1.0;
  const double touching[3] = {0.0, 0.0, 1.0}, twice[3] = {0.0, 0.0, 2.0}, far[3] = {0.0, 0.0, 1e3};
  WallAddedMass m = wall_added_mass(&floor, 1, radius, touching);
  EXPECT_DOUBLE_EQ(m.mass[2], 1.375);     // 1 + 3/8
  EXPECT_DOUBLE_EQ(m.mass[0], 1.1875);    // 1 + 3/16
  EXPECT_DOUBLE_EQ(m.mass[1], 1.1875);
  m = wall_added_mass(&floor, 1, radius, twice);
  EXPECT_DOUBLE_EQ(m.mass[2], 1.0 + 3.0 / 64.0);
  EXPECT_DOUBLE_EQ(m.mass[0], 1.0 + 3.0 / 128.0);
  m = wall_added_mass(&floor, 1, radius, far);
  EXPECT_NEAR(m.mass[2], 1.0, 1e-9);
  // In overlap: the value in contact, no gradient (no force pulling it in or out).
  const double inside[3] = {0.0, 0.0, 0.8};
  m = wall_added_mass(&floor, 1, radius, inside);
  EXPECT_DOUBLE_EQ(m.mass[2], 1.375);
  EXPECT_EQ(m.slope[2][2], 0.0);
  // A ceiling above and a floor below add their increments; the side does not matter.
  const AddedMassWall channel[2] = {{2, 0.0}, {2, 4.0}};
  const double middle[3] = {0.0, 0.0, 2.0};
  m = wall_added_mass(channel, 2, radius, middle);
  EXPECT_DOUBLE_EQ(m.mass[2], 1.0 + 2.0 * 3.0 / 64.0);
  EXPECT_NEAR(m.slope[2][2], 0.0, 1e-15);    // symmetric
}

TEST(WallAddedMass, SlopeIsTheGradient)
{
  const AddedMassWall walls[2] = {{2, 0.0}, {0, 5.0}};    // a floor and a side wall
  const double radius = 0.7, x[3] = {3.9, 0.3, 1.3}, step = 1e-6;
  const WallAddedMass m = wall_added_mass(walls, 2, radius, x);
  for (int k = 0; k < 3; k++) {
    double up[3] = {x[0], x[1], x[2]}, down[3] = {x[0], x[1], x[2]};
    up[k] += step, down[k] -= step;
    const WallAddedMass a = wall_added_mass(walls, 2, radius, up), b = wall_added_mass(walls, 2, radius, down);
    for (int d = 0; d < 3; d++)
      EXPECT_NEAR(m.slope[d][k], (a.mass[d] - b.mass[d]) / (2.0 * step), 1e-7) << d << " " << k;
  }
}

namespace {

// A sphere (mass m, added mass base * M_d(x)) under the added mass's own forces alone, as a
// fluid at rest without viscosity would move it: (m + base M_k) a_k = F_k(x, v).
struct State {
  double x[3], v[3];
};

State rate(const AddedMassWall &wall, double radius, double mass, double base, const State &s)
{
  const WallAddedMass m = wall_added_mass(&wall, 1, radius, s.x);
  double force[3];
  wall_added_mass_force(m, base, s.v, force);
  State r;
  for (int d = 0; d < 3; d++) {
    r.x[d] = s.v[d];
    r.v[d] = force[d] / (mass + base * m.mass[d]);
  }
  return r;
}

double energy(const AddedMassWall &wall, double radius, double mass, double base, const State &s)
{
  const WallAddedMass m = wall_added_mass(&wall, 1, radius, s.x);
  double e = 0.0;
  for (int d = 0; d < 3; d++)
    e += 0.5 * (mass + base * m.mass[d]) * s.v[d] * s.v[d];
  return e;
}

}    // namespace

// The forces are those of Lagrange's equations: the sphere's and the fluid's kinetic energy,
// (1/2) sum (m + M_d) v_d^2, is conserved, and so is the momentum along the wall, (m + M_x) v_x
// (x does not enter the energy); a sphere approaching the wall slows down.
TEST(WallAddedMass, LagrangeForcesConserveEnergyAndMomentumAlongTheWall)
{
  const AddedMassWall floor{2, 0.0};
  const double radius = 1.0;
  for (double density_ratio : {7.8, 1.0, 0.1}) {    // steel in water ... a bubble
    const double volume = 4.0 / 3.0 * M_PI, mass = density_ratio * volume, base = 0.5 * volume;
    State s{{0.0, 0.0, 4.0}, {0.4, 0.0, -1.0}};
    const double e0 = energy(floor, radius, mass, base, s);
    const double p0 = (mass + base * wall_added_mass(&floor, 1, radius, s.x).mass[0]) * s.v[0];
    double closest = s.x[2];
    const double dt = 1e-3;
    for (int step = 0; step < 6000 && s.x[2] > 1.02; step++) {
      const auto add = [](const State &a, const State &b, double h) {
        State c;
        for (int d = 0; d < 3; d++)
          c.x[d] = a.x[d] + h * b.x[d], c.v[d] = a.v[d] + h * b.v[d];
        return c;
      };
      const State k1 = rate(floor, radius, mass, base, s);
      const State k2 = rate(floor, radius, mass, base, add(s, k1, 0.5 * dt));
      const State k3 = rate(floor, radius, mass, base, add(s, k2, 0.5 * dt));
      const State k4 = rate(floor, radius, mass, base, add(s, k3, dt));
      for (int d = 0; d < 3; d++) {
        s.x[d] += dt / 6.0 * (k1.x[d] + 2.0 * k2.x[d] + 2.0 * k3.x[d] + k4.x[d]);
        s.v[d] += dt / 6.0 * (k1.v[d] + 2.0 * k2.v[d] + 2.0 * k3.v[d] + k4.v[d]);
      }
      closest = std::min(closest, s.x[2]);
    }
    EXPECT_NEAR(energy(floor, radius, mass, base, s), e0, 1e-10 * e0) << density_ratio;
    const double p = (mass + base * wall_added_mass(&floor, 1, radius, s.x).mass[0]) * s.v[0];
    EXPECT_NEAR(p, p0, 1e-10 * std::fabs(p0)) << density_ratio;
    EXPECT_LT(closest, 2.0) << density_ratio;              // it came close to the wall
    EXPECT_LT(s.v[2], 0.0) << density_ratio;               // the bounded mass does not stop it
    EXPECT_LT(std::fabs(s.v[2]), 1.0) << density_ratio;    // but slows it down
  }
}
