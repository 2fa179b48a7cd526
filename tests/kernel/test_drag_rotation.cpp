// The fluid's rotation and its torque on a sphere's spin (src/lubricated/drag.h,
// doc/fix_fluid_drag.rst keyword rotation).
#include "lubricated/drag.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {

// h^-1 of an upper-triangular box matrix in Voigt order (xx yy zz yz xz xy).
void invert_box(const double *h, double *h_inv)
{
  h_inv[0] = 1.0 / h[0];
  h_inv[1] = 1.0 / h[1];
  h_inv[2] = 1.0 / h[2];
  h_inv[3] = -h[3] / (h[1] * h[2]);
  h_inv[4] = (h[3] * h[5] - h[1] * h[4]) / (h[0] * h[1] * h[2]);
  h_inv[5] = -h[5] / (h[0] * h[1]);
}

// The affine velocity at position x of a box with origin 0: u = hdot h^-1 x.
void velocity_at(const double *h_rate, const double *h_inv, const double *x, double *u)
{
  const double lamda[3] = {h_inv[0] * x[0] + h_inv[5] * x[1] + h_inv[4] * x[2], h_inv[1] * x[1] + h_inv[3] * x[2],
                           h_inv[2] * x[2]};
  const double lo_rate[3] = {0.0, 0.0, 0.0};
  affine_velocity(h_rate, lo_rate, lamda, u);
}

}    // namespace

TEST(AffineVorticity, SimpleShearIsMinusTheRate)
{
  const double gdot = 2.5, h[6] = {1.0, 2.0, 3.0, 0.0, 0.0, 0.4};
  const double h_rate[6] = {0.0, 0.0, 0.0, 0.0, 0.0, gdot * h[1]};    // fix deform xy erate gdot
  double h_inv[6], curl[3];
  invert_box(h, h_inv);
  affine_vorticity(h_rate, h_inv, curl);
  EXPECT_EQ(curl[0], 0.0);
  EXPECT_EQ(curl[1], 0.0);
  EXPECT_NEAR(curl[2], -gdot, 1e-15);
}

TEST(AffineVorticity, MatchesTheCurlOfTheAffineVelocity)
{
  // A tilted box deforming in every component: the curl from central differences of u (exact
  // for a linear field up to round-off).
  const double h[6] = {1.3, 0.9, 1.7, 0.21, -0.33, 0.45}, h_rate[6] = {0.2, -0.7, 0.3, 1.1, -0.6, 0.8};
  double h_inv[6], curl[3], grad[3][3];
  invert_box(h, h_inv);
  affine_vorticity(h_rate, h_inv, curl);
  const double step = 1e-3;
  for (int j = 0; j < 3; j++) {
    double xp[3] = {0.3, 0.2, 0.5}, xm[3] = {0.3, 0.2, 0.5}, up[3], um[3];
    xp[j] += step;
    xm[j] -= step;
    velocity_at(h_rate, h_inv, xp, up);
    velocity_at(h_rate, h_inv, xm, um);
    for (int k = 0; k < 3; k++)
      grad[k][j] = (up[k] - um[k]) / (2.0 * step);    // du_k / dx_j
  }
  EXPECT_NEAR(curl[0], grad[2][1] - grad[1][2], 1e-12);
  EXPECT_NEAR(curl[1], grad[0][2] - grad[2][0], 1e-12);
  EXPECT_NEAR(curl[2], grad[1][0] - grad[0][1], 1e-12);
}

TEST(RotationalDrag, StokesCoefficient)
{
  EXPECT_DOUBLE_EQ(rotational_drag_coefficient(2.0, 0.5), 8.0 * pi * 0.5 * 8.0);
}

TEST(RotationalDrag, SmallStepIsTheStokesTorque)
{
  const double beta = 3.0, inertia = 1.0, dt = 1e-9, slip[3] = {0.5, -1.0, 2.0}, other[3] = {0.0, 0.0, 0.0};
  double torque[3];
  implicit_drag_torque(beta, inertia, dt, slip, other, torque);
  for (int d = 0; d < 3; d++)
    EXPECT_NEAR(torque[d], beta * slip[d], 1e-8 * std::abs(beta * slip[d]));
}

TEST(RotationalDrag, SteadySpinBalancesTheOtherTorques)
{
  // omega = Omega_f + T_o / beta: the drag cancels T_o, for any step.
  const double beta = 2.0, inertia = 0.1, other[3] = {0.4, -0.2, 1.0};
  for (double dt : {1e-4, 0.05, 10.0}) {
    const double slip[3] = {-other[0] / beta, -other[1] / beta, -other[2] / beta};
    double torque[3];
    implicit_drag_torque(beta, inertia, dt, slip, other, torque);
    for (int d = 0; d < 3; d++)
      EXPECT_NEAR(torque[d], -other[d], 1e-15);
  }
}

TEST(RotationalDrag, StiffStepsRelaxWithoutOvershoot)
{
  // Steps of k = beta dt / I up to 100: the spin moves monotonically to the fluid's, as
  // omega_n = Omega + (omega_0 - Omega) / (1 + k)^n.
  const double beta = 1.0, inertia = 1.0, fluid = -0.5, other[3] = {0.0, 0.0, 0.0};
  for (double k : {0.01, 1.0, 100.0}) {
    const double dt = k * inertia / beta;
    double omega = 3.0;
    for (int n = 1; n <= 20; n++) {
      const double slip[3] = {0.0, 0.0, fluid - omega};
      double torque[3];
      implicit_drag_torque(beta, inertia, dt, slip, other, torque);
      omega += dt * torque[2] / inertia;
      EXPECT_NEAR(omega, fluid + 3.5 / std::pow(1.0 + k, n), 1e-12);
      EXPECT_GE(omega, fluid);    // never past the fluid's spin
    }
  }
}
