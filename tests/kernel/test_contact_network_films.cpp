// The contact-network check with the films of the coupled solve (lubricated/contact_network.h):
// a film solved implicitly acts on the velocity the step ends with,
//   y' - 2 y + y'' = -(K y + C (y - y'')) - D (y' - y),   D = sum_k a_k b_k b_k^T,
// and the step is stable when S < 4 I + 2 D. On the random networks of test_contact_network.cpp,
// where the check without the films finds growth at the same loads: the upper bound with the
// relieved loads (s_k - 2 a_k)^+ proves stability, and the check's lower bound (the contact's own
// film alone) stops every network whose growth the relieved loads prove.
#include "lubricated/contact_network.h"

#include "contact_network_systems.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace contact_network_test;

namespace {

// out += sum_k w_k b_k (b_k . y), per-contact weights.
void accumulate_weighted(const Network &net, const std::vector<double> &w, const std::vector<double> &y,
                         std::vector<double> &out)
{
  for (std::size_t k = 0; k < net.contacts.size(); k++) {
    const Contact &c = net.contacts[k];
    const double a = w[k] * project(net, c, y) * std::sqrt(c.m_e);
    for (int d = 0; d < 3; d++) {
      out[3 * c.i + d] += a * c.n[d] / std::sqrt(net.mass[c.i]);
      out[3 * c.j + d] -= a * c.n[d] / std::sqrt(net.mass[c.j]);
    }
  }
}

// x := (I + D)^-1 r by conjugate gradients (I + D is symmetric positive definite).
void solve_films(const Network &net, const std::vector<double> &a, const std::vector<double> &r, std::vector<double> &x)
{
  const std::size_t n = r.size();
  std::vector<double> res = r, p = r, q(n);
  x.assign(n, 0.0);
  double rr = 0.0, rr0 = 0.0;
  for (double v : r)
    rr0 += v * v;
  rr = rr0;
  for (int it = 0; it < 2000 && rr > 1e-28 * rr0 && rr > 0.0; it++) {
    q = p;
    accumulate_weighted(net, a, p, q);
    double pq = 0.0;
    for (std::size_t e = 0; e < n; e++)
      pq += p[e] * q[e];
    const double alpha = rr / pq;
    double next = 0.0;
    for (std::size_t e = 0; e < n; e++) {
      x[e] += alpha * p[e], res[e] -= alpha * q[e];
      next += res[e] * res[e];
    }
    for (std::size_t e = 0; e < n; e++)
      p[e] = res[e] + next / rr * p[e];
    rr = next;
  }
}

// Largest |y| over `steps` steps of the step with films a_k (per contact) from a random start.
double largest_amplitude_with_films(const Network &net, double kappa, double gamma, const std::vector<double> &a,
                                    int steps, std::mt19937_64 &rng)
{
  std::normal_distribution<double> normal;
  const std::size_t size = 3 * net.mass.size();
  std::vector<double> y(size), u(size, 0.0), rhs(size), next(size);
  double norm = 0.0;
  for (double &v : y)
    v = normal(rng), norm += v * v;
  for (double &v : y)
    v /= std::sqrt(norm);
  double largest = 1.0;
  for (int n = 0; n < steps && largest < 1e9; n++) {
    rhs = u;
    std::vector<double> force(size, 0.0);
    accumulate(net, y, kappa, true, force);
    accumulate(net, u, gamma, true, force);
    for (std::size_t q = 0; q < size; q++)
      rhs[q] -= force[q];
    solve_films(net, a, rhs, u);    // (I + D) u' = u - K y - C u
    norm = 0.0;
    for (std::size_t q = 0; q < size; q++)
      y[q] += u[q], norm += y[q] * y[q];
    largest = std::max(largest, std::sqrt(norm));
  }
  return largest;
}

// The check's bounds with the films a_k (dt = 1: dt c_k = a_k m_e,k): the largest upper row with
// the relieved loads and the largest lower quotient less the contact's own film (the check's),
// and the largest Rayleigh quotient of the b_k for the relieved loads (a proof of growth where
// the films are proportional to the loads).
struct FilmBounds {
  double upper = 0.0, lower = 0.0, relieved_lower = 0.0;
};
FilmBounds bounds_with_films(const Network &net, double s, const std::vector<double> &a)
{
  std::vector<double> sums(network_values * net.mass.size(), 0.0), relieved_sums(sums.size(), 0.0);
  std::vector<double> relieved(net.contacts.size());
  for (std::size_t k = 0; k < net.contacts.size(); k++) {
    const Contact &c = net.contacts[k];
    relieved[k] = film_relieved_load(s, a[k] * c.m_e, 1.0, c.m_e);
    for (int atom : {c.i, c.j}) {
      add_network_contact(&sums[network_values * atom], s, relieved[k], c.m_e, c.n);
      add_network_contact(&relieved_sums[network_values * atom], relieved[k], relieved[k], c.m_e, c.n);
    }
  }
  FilmBounds b;
  for (std::size_t k = 0; k < net.contacts.size(); k++) {
    const Contact &c = net.contacts[k];
    const double mi = net.mass[c.i], mj = net.mass[c.j];
    const double *si = &sums[network_values * c.i], *sj = &sums[network_values * c.j];
    const double *ri = &relieved_sums[network_values * c.i], *rj = &relieved_sums[network_values * c.j];
    b.upper = std::max(b.upper, network_upper_row(relieved[k], c.m_e, si, mi, sj, mj));
    b.lower = std::max(b.lower, network_lower_quotient(s, c.m_e, c.n, si, mi, sj, mj) - 2.0 * a[k]);
    b.relieved_lower = std::max(b.relieved_lower, network_lower_quotient(relieved[k], c.m_e, c.n, ri, mi, rj, mj));
  }
  return b;
}

}    // namespace

TEST(ContactNetworkFilms, SolvedFilmsStabiliseAndTheBoundsSaySo)
{
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.5, 1.0);
  const Network unit = random_network(rng, 40, 0.8, 1.0, 1.0);
  double upper0, lower0;
  bounds(unit, upper0, lower0);
  int rescued = 0, proven_stable = 0, proven_growing = 0;
  for (double e : {0.5, 0.9})
    for (double n : {1.0, 1.5, 2.0}) {
      const double s = contact_load_of_steps(e, n);
      const double E = std::pow(e, 1.0 / std::max(n, 1.5)), C = std::cos(3.14159265358979323846 / std::max(n, 1.5));
      const double kappa = 1.0 + E * E - 2.0 * E * C, gamma = 1.0 - E * E;
      for (double strength : {0.0, 0.5, 2.0, 8.0})
        for (bool uniform : {true, false}) {
          std::vector<double> a(unit.contacts.size());
          for (double &v : a)
            v = strength * (uniform ? 1.0 : u(rng));
          const FilmBounds b = bounds_with_films(unit, s, a);
          const double amplitude = largest_amplitude_with_films(unit, kappa, gamma, a, 300, rng);
          const auto what = ::testing::Message() << "e_d " << e << " N_c " << n << " films " << strength;
          if (b.upper < stable_network_load) {
            EXPECT_LT(amplitude, 1e3) << what;
            proven_stable++;
            // Without the films the check proves growth here, and the step grows.
            if (lower0 * s >= stable_network_load && strength > 0.0) {
              EXPECT_GT(largest_amplitude(unit, kappa, gamma, 300, rng), 1e6) << what;
              rescued++;
            }
          }
          // Proportional films (one load, one a): the relieved loads' lower bound is a proof of
          // growth, and the check's (own film alone, never below it) stops the run.
          if (uniform && b.relieved_lower >= stable_network_load) {
            EXPECT_GT(amplitude, 1e6) << what;
            EXPECT_GE(b.lower, stable_network_load) << what;
            proven_growing++;
          }
        }
    }
  EXPECT_GE(rescued, 4);
  EXPECT_GE(proven_stable, 8);
  EXPECT_GE(proven_growing, 4);
}
