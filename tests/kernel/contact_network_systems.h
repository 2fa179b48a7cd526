// Test networks for the contact-network check (lubricated/contact_network.h): random spheres
// with radii 1:10 in contact where they overlap, the products with S = sum_k s_k b_k b_k^T in
// mass-weighted coordinates, the largest eigenvalue, the check's bounds, and the linearised step
// y' - 2 y + y'' = -(K y + C (y - y'')) of such a network.
#pragma once

#include "lubricated/contact_network.h"

#include <cmath>
#include <random>
#include <vector>

namespace contact_network_test {

using namespace lubricated;


struct Contact {
  int i, j;
  double n[3];
  double m_e;
  double s;    // load (normal)
};

struct Network {
  std::vector<double> mass;
  std::vector<Contact> contacts;
};

// Spheres with radii 1:10 (log-uniform) at random in a box, in contact where they overlap.
inline Network random_network(std::mt19937_64 &rng, int n, double box, double load_lo, double load_hi)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Network net;
  std::vector<double> x(3 * n), r(n);
  for (int i = 0; i < n; i++) {
    r[i] = 0.1 * std::exp(std::log(10.0) * u(rng));
    net.mass.push_back(r[i] * r[i] * r[i]);
    for (int d = 0; d < 3; d++)
      x[3 * i + d] = box * u(rng);
  }
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++) {
      double del[3], rsq = 0.0;
      for (int d = 0; d < 3; d++)
        del[d] = x[3 * i + d] - x[3 * j + d], rsq += del[d] * del[d];
      if (rsq >= (r[i] + r[j]) * (r[i] + r[j])) continue;
      Contact c{
          i, j, {}, net.mass[i] * net.mass[j] / (net.mass[i] + net.mass[j]), load_lo + (load_hi - load_lo) * u(rng)};
      for (int d = 0; d < 3; d++)
        c.n[d] = del[d] / std::sqrt(rsq);
      net.contacts.push_back(c);
    }
  return net;
}

inline double project(const Network &net, const Contact &c, const std::vector<double> &y)
{
  double p = 0.0;
  for (int d = 0; d < 3; d++)
    p += c.n[d] * (y[3 * c.i + d] / std::sqrt(net.mass[c.i]) - y[3 * c.j + d] / std::sqrt(net.mass[c.j]));
  return std::sqrt(c.m_e) * p;
}

// out += sum_k w_k b_k (b_k . y), w_k = weight * s_k (or weight if unit).
inline void accumulate(const Network &net, const std::vector<double> &y, double weight, bool unit, std::vector<double> &out)
{
  for (const Contact &c : net.contacts) {
    const double a = weight * (unit ? 1.0 : c.s) * project(net, c, y) * std::sqrt(c.m_e);
    for (int d = 0; d < 3; d++) {
      out[3 * c.i + d] += a * c.n[d] / std::sqrt(net.mass[c.i]);
      out[3 * c.j + d] -= a * c.n[d] / std::sqrt(net.mass[c.j]);
    }
  }
}

inline double largest_eigenvalue(const Network &net, std::mt19937_64 &rng, bool unit = false)
{
  std::normal_distribution<double> normal;
  std::vector<double> y(3 * net.mass.size());
  for (double &v : y)
    v = normal(rng);
  double lambda = 0.0;
  for (int it = 0; it < 1500; it++) {
    double norm = 0.0;
    for (double v : y)
      norm += v * v;
    for (double &v : y)
      v /= std::sqrt(norm);
    std::vector<double> z(y.size(), 0.0);
    accumulate(net, y, 1.0, unit, z);
    lambda = 0.0;
    for (std::size_t k = 0; k < y.size(); k++)
      lambda += y[k] * z[k];    // Rayleigh quotient
    y = z;
  }
  return lambda;
}

// The per-atom sums and the largest upper row and lower quotient over the contacts.
inline void bounds(const Network &net, double &upper, double &lower)
{
  std::vector<double> sums(network_values * net.mass.size(), 0.0);
  for (const Contact &c : net.contacts) {
    add_network_contact(&sums[network_values * c.i], c.s, c.s, c.m_e, c.n);
    add_network_contact(&sums[network_values * c.j], c.s, c.s, c.m_e, c.n);
  }
  upper = lower = 0.0;
  for (const Contact &c : net.contacts) {
    const double *si = &sums[network_values * c.i], *sj = &sums[network_values * c.j];
    upper = std::max(upper, network_upper_row(c.s, c.m_e, si, net.mass[c.i], sj, net.mass[c.j]));
    lower = std::max(lower, network_lower_quotient(c.s, c.m_e, c.n, si, net.mass[c.i], sj, net.mass[c.j]));
  }
}

// Largest |y| over `steps` steps of the recurrence with per-step kappa and gamma on every contact,
// from a random start with |y| = 1 (y'' = y).
inline double largest_amplitude(const Network &net, double kappa, double gamma, int steps, std::mt19937_64 &rng)
{
  std::normal_distribution<double> normal;
  const std::size_t size = 3 * net.mass.size();
  std::vector<double> y(size), last(size), next(size), diff(size), force(size);
  double norm = 0.0;
  for (double &v : y)
    v = normal(rng), norm += v * v;
  for (std::size_t q = 0; q < size; q++)
    last[q] = y[q] /= std::sqrt(norm);
  double largest = 1.0;
  for (int n = 0; n < steps && largest < 1e9; n++) {
    for (std::size_t q = 0; q < size; q++)
      diff[q] = y[q] - last[q], force[q] = 0.0;
    accumulate(net, y, kappa, true, force);
    accumulate(net, diff, gamma, true, force);
    norm = 0.0;
    for (std::size_t q = 0; q < size; q++) {
      next[q] = 2.0 * y[q] - last[q] - force[q];
      norm += next[q] * next[q];
    }
    last.swap(y);
    y.swap(next);
    largest = std::max(largest, std::sqrt(norm));
  }
  return largest;
}

}    // namespace contact_network_test
