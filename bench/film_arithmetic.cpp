/* ----------------------------------------------------------------------
   film_arithmetic: what one film-only pair costs the vectorised loops of pair_style
   lubricated/springdashpot (src/pair_lubricated_springdashpot/vector_pairs.h), in ns per pair,
   one core, with the data in the cache (issue 19, bench/wet_cost.py):
     film_gathered    vector_pairs::film_only as the pair style calls it: pairs of a random
                      2000-atom set, x, v, radius and mass gathered per pair;
     film_contiguous  the same arithmetic (geometry, lubricated::film_force_apart, its outputs)
                      on per-pair arrays read in order: no gathers, the film's arithmetic alone;
     shear_gathered   vector_pairs::film_shear_only (friction: the shear film too), gathered.
   No scatter of forces (the pair style's scatter comes on top). Pairs: radii 0.9-1.1 mm,
   2500 kg/m^3, gaps 1-90 um (in the film of grid 1.25e-4 m), relative speeds up to 0.2 m/s
   per component, dt 1.25e-5 s, water (the beds of bench/independent_beds.py). Prints
   "RESULT name ns" lines, each the best of 5 rounds. Built by `make bench-wet-cost` (CMake target
   film_arithmetic, not part of the default build).
------------------------------------------------------------------------- */

#include "lubricated/contact.h"
#include "lubricated/vector_clones.h"
#include "pair_lubricated_springdashpot/vector_pairs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace lub = lubricated;
namespace vp = LAMMPS_NS::vector_pairs;

// The pairs' data in order (d: x_i - x_j, w: v_i - v_j).
struct PairArrays {
  std::vector<double> dx, dy, dz, wx, wy, wz, radius_i, radius_j, mass_i, mass_j;
};

// vector_pairs.cpp's film_only_loop without its gathers: the same geometry, film and outputs.
LUBRICATED_VECTOR_CLONES __attribute__((noinline)) static void
film_contiguous(const lub::NormalModel &model, const PairArrays &p, int first, int n, double *__restrict fx,
                double *__restrict fy, double *__restrict fz, double *__restrict film, double *__restrict capacity)
{
  const lub::Lubrication law = model.lubrication;
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  const double *__restrict dx = &p.dx[first], *__restrict dy = &p.dy[first], *__restrict dz = &p.dz[first];
  const double *__restrict wx = &p.wx[first], *__restrict wy = &p.wy[first], *__restrict wz = &p.wz[first];
  const double *__restrict ri = &p.radius_i[first], *__restrict rj = &p.radius_j[first];
  const double *__restrict mi = &p.mass_i[first], *__restrict mj = &p.mass_j[first];
  for (int c = 0; c < n; c++) {
    const double r = std::sqrt(dx[c] * dx[c] + dy[c] * dy[c] + dz[c] * dz[c]), rinv = 1.0 / r;
    const double u_n = (wx[c] * dx[c] + wy[c] * dy[c] + wz[c] * dz[c]) * rinv;
    const lub::FilmRadius radius = lub::film_radius_pair(ri[c], rj[c]);
    const double m_e = mi[c] * mj[c] / (mi[c] + mj[c]);
    const double f = lub::film_force_apart<true>(law, r - ri[c] - rj[c], radius, m_e, u_n, dt, inv_dt);
    const double fpair = rinv * f;
    fx[c] = dx[c] * fpair, fy[c] = dy[c] * fpair, fz[c] = dz[c] * fpair;
    film[c] = f;
    capacity[c] = lub::film_capacity(m_e, u_n);
  }
}

int main()
{
  constexpr int atoms = 2000, chunk = 256, pairs = 40 * chunk, rounds = 5, sweeps = 1000;
  constexpr double dt = 1.25e-5;
  lub::Coefficients c;
  c.e_dry = 0.9, c.n_contact = 8, c.viscosity = 1e-3, c.grid_spacing = 1.25e-4, c.friction = 0.3;
  const lub::ContactModel model = lub::make_contact_model(c, lub::Partner::particle, dt);

  std::mt19937 random(19);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> x(3 * atoms), v(3 * atoms), omega(3 * atoms), radius(atoms), mass(atoms);
  for (int k = 0; k < atoms; k++) {
    radius[k] = 0.9e-3 + 0.2e-3 * unit(random);
    mass[k] = 2500.0 * 4.0 / 3.0 * M_PI * radius[k] * radius[k] * radius[k];
    for (int d = 0; d < 3; d++) {
      x[3 * k + d] = 0.05 * unit(random);
      v[3 * k + d] = 0.2 * unit(random) - 0.1;
      omega[3 * k + d] = 200.0 * unit(random) - 100.0;
    }
  }
  // Each pair puts j at a gap of 1-90 um from i in a random direction (a later pair may move j
  // again: only the timed pairs' own geometry matters, and those are rebuilt below).
  std::vector<int> pair_i(pairs), pair_j(pairs);
  for (int k = 0; k < pairs; k++) {
    const int i = static_cast<int>(random() % atoms);
    const int j = (i + 1 + static_cast<int>(random() % (atoms - 1))) % atoms;
    pair_i[k] = i, pair_j[k] = j;
    const double gap = 1e-6 + 89e-6 * unit(random), phi = 2.0 * M_PI * unit(random), z = 2.0 * unit(random) - 1.0;
    const double s = std::sqrt(1.0 - z * z), d = radius[i] + radius[j] + gap;
    x[3 * j] = x[3 * i] + d * s * std::cos(phi), x[3 * j + 1] = x[3 * i + 1] + d * s * std::sin(phi);
    x[3 * j + 2] = x[3 * i + 2] + d * z;
  }
  PairArrays p;
  for (int k = 0; k < pairs; k++) {
    const int i = pair_i[k], j = pair_j[k];
    p.dx.push_back(x[3 * i] - x[3 * j]), p.dy.push_back(x[3 * i + 1] - x[3 * j + 1]);
    p.dz.push_back(x[3 * i + 2] - x[3 * j + 2]);
    p.wx.push_back(v[3 * i] - v[3 * j]), p.wy.push_back(v[3 * i + 1] - v[3 * j + 1]);
    p.wz.push_back(v[3 * i + 2] - v[3 * j + 2]);
    p.radius_i.push_back(radius[i]), p.radius_j.push_back(radius[j]);
    p.mass_i.push_back(mass[i]), p.mass_j.push_back(mass[j]);
  }

  std::vector<double> out(16 * chunk);
  double *o = out.data();
  const vp::Atoms gathered{x.data(), v.data(), radius.data(), mass.data(), nullptr, omega.data()};
  const vp::ForceOut force{o, o + chunk, o + 2 * chunk};
  const vp::ShearOut shear{o,  o + chunk,  o + 2 * chunk,  o + 5 * chunk,  o + 6 * chunk, o + 7 * chunk,
                           o + 8 * chunk, o + 9 * chunk, o + 10 * chunk, o + 11 * chunk, o + 12 * chunk};
  double sink = 0.0;
  auto best_ns = [&](auto &&sweep) {
    double best = INFINITY;
    for (int round = 0; round < rounds; round++) {
      const auto start = std::chrono::steady_clock::now();
      for (int s = 0; s < sweeps; s++) {
        for (int first = 0; first < pairs; first += chunk)
          sweep(first);
        sink += o[s % chunk];
      }
      const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
      best = std::min(best, took.count() * 1e9 / (static_cast<double>(sweeps) * pairs));
    }
    return best;
  };
  const double film_gathered = best_ns([&](int first) {
    vp::film_only(gathered, model.normal, &pair_i[first], &pair_j[first], chunk, force, o + 3 * chunk, o + 4 * chunk);
  });
  const double contiguous = best_ns([&](int first) {
    film_contiguous(model.normal, p, first, chunk, o, o + chunk, o + 2 * chunk, o + 3 * chunk, o + 4 * chunk);
  });
  const double shear_gathered = best_ns([&](int first) {
    vp::film_shear_only(gathered, model, &pair_i[first], &pair_j[first], chunk, o + 3 * chunk, o + 4 * chunk, shear,
                        false);
  });
  std::printf("RESULT film_gathered %.3f\nRESULT film_contiguous %.3f\nRESULT shear_gathered %.3f\n", film_gathered,
              contiguous, shear_gathered);
  return sink == 12345.678 ? 1 : 0;    // keeps the results alive
}
