/* ----------------------------------------------------------------------
   film_solve_cost: what the coupled film solve (src/lubricated/film_solve.h, doc/film_solve.rst)
   costs, in ns per sphere and conjugate-gradient iteration, one core, one process (no ghosts),
   and how many iterations it takes, on a dense packing: a jittered fcc block of spheres of
   radii 0.9-1.0 mm, nearest surfaces 2-200 um apart (solid fraction about 0.6), every pair within
   the film's reach eps_al = 0.1 a film with its normal coefficient (Lubrication::damping) and
   its shear coefficient 2 pi mu R_e ln(eps_al / max(eps, eps_1)) (tangential.h), random
   velocities and forces. The viscosity is chosen so that a film at saturation has the share
   c_n dt / m_e given on the command line (issue 45 measured an average of 87 in a St 1e-3
   suspension). Prints "RESULT" lines: spheres, films per sphere, preconditioner, tolerance,
   iterations, converged, ns per sphere and iteration (best of 3 solves).
   Not built by default; e.g.
     g++ -O3 -march=native -std=gnu++17 -Isrc bench/film_solve_cost.cpp -o film_solve_cost
     ./film_solve_cost [cells per side, default 16] [share, default 100]
------------------------------------------------------------------------- */

#include "lubricated/film_solve.h"
#include "lubricated/lubrication.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace lub = lubricated;

namespace {

struct Packing {
  std::vector<double> inverse_mass, inverse_inertia, radius, velocity, force, x;
  std::vector<lub::FilmLink> links;
};

Packing make_packing(int cells, double share)
{
  const double a = 1e-3, density = 2500.0, dt = 1e-5, eps_al = 0.1, eps_1 = 1e-3;
  const double spacing = 2.0 * a * 1.001 * std::sqrt(2.0);    // fcc cube edge: nearest 2.002 a
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  Packing p;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  for (int c = 0; c < cells * cells * cells; c++)
    for (const auto &b : basis) {
      const int cell[3] = {c % cells, (c / cells) % cells, c / (cells * cells)};
      const double r = a * (0.9 + 0.1 * u(rng)), m = density * 4.18879 * r * r * r;
      for (int d = 0; d < 3; d++)
        p.x.push_back((cell[d] + b[d]) * spacing + 0.002 * a * (u(rng) - 0.5));
      p.radius.push_back(r);
      p.inverse_mass.push_back(1.0 / m);
      p.inverse_inertia.push_back(1.0 / lub::sphere_inertia(m, r));
      for (int d = 0; d < lub::film_dofs; d++)
        p.velocity.push_back(0.01 * g(rng)), p.force.push_back(1e-4 * g(rng));
    }
  const int n = int(p.radius.size());
  const double m_min = density * 4.18879 * std::pow(0.9 * a, 3);
  // mu such that a saturated film between two of the smallest spheres has the share asked for.
  const lub::Lubrication unit = lub::make_lubrication(lub::Partner::particle, 1.0, eps_al, 0.0, eps_1, -1e-2);
  const double mu = share * 0.5 * m_min / (dt * unit.damping(eps_1, 0.9 * a));
  const lub::Lubrication film = lub::make_lubrication(lub::Partner::particle, mu, eps_al, 0.0, eps_1, -1e-2);
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++) {
      double d[3], r2 = 0.0;
      for (int k = 0; k < 3; k++)
        d[k] = p.x[3 * i + k] - p.x[3 * j + k], r2 += d[k] * d[k];
      if (r2 > 9.0 * a * a) continue;
      const double distance = std::sqrt(r2), gap = distance - p.radius[i] - p.radius[j];
      const lub::FilmRadius film_radius = lub::film_radius_pair(p.radius[i], p.radius[j]);
      const double eps = gap * film_radius.inverse;
      if (eps >= eps_al) continue;
      lub::FilmLink l;
      l.i = i, l.j = j;
      l.normal = {d[0] / distance, d[1] / distance, d[2] / distance};
      l.normal_damping = film.damping(eps, film_radius.value);
      l.shear_damping = 2.0 * lub::pi * mu * 0.5 * film_radius.value * std::log(eps_al / std::max(eps, eps_1));
      p.links.push_back(l);
    }
  return p;
}

void measure(const Packing &p, lub::FilmPreconditioner preconditioner, double tolerance)
{
  lub::FilmAtoms atoms;
  atoms.owned = atoms.total = int(p.radius.size());
  atoms.inverse_mass = p.inverse_mass.data();
  atoms.inverse_inertia = p.inverse_inertia.data();
  atoms.radius = p.radius.data();
  lub::FilmSolveOptions options;
  options.tolerance = tolerance;
  options.max_iterations = 5000;
  options.preconditioner = preconditioner;
  std::vector<double> increment(p.velocity.size());
  lub::FilmSolver solver;
  double best = 1e300;
  lub::FilmSolveResult r;
  for (int round = 0; round < 3; round++) {
    const auto start = std::chrono::steady_clock::now();
    r = solver.solve(atoms, p.links.data(), int(p.links.size()), 1e-5, p.velocity.data(), p.force.data(),
                     increment.data(), options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, seconds);
  }
  const int n = atoms.owned;
  std::printf("RESULT spheres %d films_per_sphere %.2f preconditioner %s tolerance %.0e iterations %d converged %d "
              "ns_per_sphere_iteration %.1f\n",
              n, 2.0 * p.links.size() / n, preconditioner == lub::FilmPreconditioner::block ? "block" : "mass",
              tolerance, r.iterations, int(r.converged), 1e9 * best / (double(n) * std::max(1, r.iterations)));
}

}    // namespace

int main(int argc, char **argv)
{
  const int cells = argc > 1 ? std::atoi(argv[1]) : 16;
  const double share = argc > 2 ? std::atof(argv[2]) : 100.0;
  const Packing p = make_packing(cells, share);
  std::printf("# fcc block %d^3 cells, saturated film share %g\n", cells, share);
  for (double tolerance : {1e-6, 1e-8})
    for (auto preconditioner : {lub::FilmPreconditioner::mass, lub::FilmPreconditioner::block})
      measure(p, preconditioner, tolerance);
  return 0;
}
