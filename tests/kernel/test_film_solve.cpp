// The coupled film solve (lubricated/film_solve.h, doc/film_solve.rst): the backward-Euler step
// (M + dt R) w' = M w + dt (F + f_wall) of all films against a dense direct solve
// (film_solve_systems.h), the scalar implicit formula of an isolated pair, the energy identity,
// zero films, the iteration limit, the warm start along a trajectory, kept preconditioner blocks
// and very stiff films.
#include "film_solve_systems.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace film_solve_test;

TEST(FilmSolve, MatchesDenseDirectSolve)
{
  const double dt = 1e-3;
  int most = 0;
  for (unsigned seed = 1; seed <= 20; seed++) {
    const System s = random_system(seed, 12, 20, 4, dt, seed % 2 ? 3.0 : 300.0, true);
    FilmSolveResult r;
    const std::vector<double> w = film_step(s, dt, &r);
    EXPECT_TRUE(r.converged);
    most = std::max(most, r.iterations);
    EXPECT_LT(relative_difference(w, dense_step(s, dt)), 1e-10) << "seed " << seed;
  }
  std::printf("[ iterations ] 12 atoms, 24 films, tolerance 1e-13: at most %d\n", most);
}

TEST(FilmSolve, DragIsSolvedWithTheFilms)
{
  const double dt = 1e-3;
  System s = random_system(21, 12, 20, 3, dt, 30.0, true);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < s.n(); i++) {
    s.drag.push_back(1e4 * u(rng));
    s.rotational_drag.push_back(1e3 * u(rng));
    for (int d = 0; d < film_dofs; d++)    // the caller's explicit drag at w, fluid at rest
      s.force[6 * i + d] -= (d < 3 ? s.drag[i] : s.rotational_drag[i]) * s.velocity[6 * i + d];
  }
  const std::vector<double> expected = dense_step(s, dt);
  EXPECT_LT(relative_difference(film_step(s, dt), expected), 1e-10);
  FilmSolveOptions plain;
  plain.preconditioner = FilmPreconditioner::mass;
  EXPECT_LT(relative_difference(film_step(s, dt, nullptr, plain), expected), 1e-10);
}

TEST(FilmSolve, IsolatedPairIsTheScalarImplicitStep)
{
  // Unequal spheres along x; normal approach and tangential slip with rotation: the implicit
  // step of the normal mode m_e (u' - u) = -dt c_n u' and of the slip mode m_t (s' - s) =
  // -dt c_t s' (m_t = 2/7 m_e for solid spheres), momentum kept.
  const double dt = 1e-4, ra = 1.0, rb = 1.4, ma = 4.18879 * ra * ra * ra, mb = 4.18879 * rb * rb * rb;
  System s;
  s.radius = {ra, rb};
  s.inverse_mass = {1.0 / ma, 1.0 / mb};
  s.inverse_inertia = {1.0 / sphere_inertia(ma, ra), 1.0 / sphere_inertia(mb, rb)};
  s.velocity = {-1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.5, -0.2, 0.0, 0.0, 0.0, 0.0};
  s.force.assign(12, 0.0);
  FilmLink l;
  l.i = 0, l.j = 1, l.normal = {1.0, 0.0, 0.0}, l.normal_damping = 7e4, l.shear_damping = 3e4;
  s.links = {l};
  const std::vector<double> w = film_step(s, dt);
  const double me = ma * mb / (ma + mb), mt = tangential_mass_ratio * me;
  const double u = -1.5, u_next = me * u / (me + dt * l.normal_damping);
  const double slip = 0.5, slip_next = mt * slip / (mt + dt * l.shear_damping);
  EXPECT_NEAR(w[0] - w[6], u_next, 1e-13);
  const double slip_after = (w[1] - w[7]) - (ra * w[5] + rb * w[11]);    // ((R w) x n)_y = R w_z
  EXPECT_NEAR(slip_after, slip_next, 1e-13);
  EXPECT_NEAR(ma * w[0] + mb * w[6], ma * -1.0 + mb * 0.5, 1e-12);
  EXPECT_NEAR(ma * w[1] + mb * w[7], ma * 0.3 - mb * 0.2, 1e-12);
  // A wall: m (u' - u) = -dt c u' with u relative to the moving wall.
  System wall = s;
  wall.links[0].j = -1, wall.links[0].shear_damping = 0.0, wall.links[0].wall_velocity = {0.25, 0.0, 0.0};
  const std::vector<double> ww = film_step(wall, dt);
  EXPECT_NEAR(ww[0] - 0.25, ma * (-1.25) / (ma + dt * l.normal_damping), 1e-13);
  // A sphere whose only partners are walls: its 6x6 block (both films, translation and rotation
  // coupled, two walls) is the whole operator, so the block preconditioner solves in one step.
  wall.links[0].shear_damping = 3e4;
  FilmLink side = wall.links[0];
  side.normal = {0.0, 0.6, 0.8}, side.normal_damping = 2e3, side.shear_damping = 5e4;
  wall.links.push_back(side);
  FilmSolveResult one;
  const std::vector<double> exact = film_step(wall, dt, &one);
  EXPECT_EQ(one.iterations, 1);
  EXPECT_LT(relative_difference(exact, dense_step(wall, dt)), 1e-13);
}

TEST(FilmSolve, KineticEnergyNeverRisesAndMatchesTheDissipation)
{
  const double dt = 1e-3;
  for (unsigned seed = 1; seed <= 40; seed++) {
    System s = random_system(100 + seed, 30, 90, 6, dt, seed % 3 == 0 ? 1e3 : 5.0, false);
    at_rest_outside(s);
    const std::vector<double> w = film_step(s, dt);
    const double before = kinetic_energy(s, s.velocity), after = kinetic_energy(s, w);
    EXPECT_LE(after, before * (1.0 + 1e-13)) << "seed " << seed;
    // before - after = 1/2 |w' - w|_M^2 + dt w'^T R w' (doc/film_solve.rst).
    std::vector<double> force(w.size()), step(w.size());
    film_forces(s.atoms(), s.links.data(), int(s.links.size()), w.data(), false, force.data());
    double dissipated = 0.0;
    for (size_t e = 0; e < w.size(); e++)
      dissipated -= dt * w[e] * force[e], step[e] = w[e] - s.velocity[e];
    EXPECT_NEAR(before - after, kinetic_energy(s, step) + dissipated, 1e-9 * before) << "seed " << seed;
  }
}

TEST(FilmSolve, ZeroFilmsGiveTheFreeStepExactly)
{
  const double dt = 1e-3;
  System s = random_system(7, 10, 0, 0, dt, 1.0, true);
  FilmSolveResult r;
  const std::vector<double> w = film_step(s, dt, &r);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 1);
  for (int e = 0; e < 6 * s.n(); e++) {
    const double inverse = e % 6 < 3 ? s.inverse_mass[e / 6] : s.inverse_inertia[e / 6];
    EXPECT_EQ(w[e], s.velocity[e] + dt * s.force[e] * inverse);
  }
}

TEST(FilmSolve, IterationLimitIsHonoured)
{
  const double dt = 1e-3;
  const System s = random_system(3, 40, 150, 5, dt, 1e3, true);
  FilmSolveOptions options;
  options.max_iterations = 3;
  options.tolerance = 1e-12;
  std::vector<double> x(s.velocity.size());
  FilmSolver solver;
  const FilmSolveResult r = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(),
                                         s.force.data(), x.data(), options);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.residual, 1e-12);
  EXPECT_LT(r.residual, 1.0);
  // Started from the converged increment, a warm start has nothing to do.
  options.max_iterations = 2000;
  const FilmSolveResult full = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(),
                                            s.force.data(), x.data(), options);
  EXPECT_TRUE(full.converged);
  options.warm_start = true;
  options.tolerance = 1e-10;
  const FilmSolveResult warm = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(),
                                            s.force.data(), x.data(), options);
  EXPECT_TRUE(warm.converged);
  EXPECT_EQ(warm.iterations, 0);
}

// Steps along a trajectory whose increments change linearly (the force F_n = F_0 + n dF on fixed
// films, so x_n = x_0 + n dx): started from film_increment_guess, the last step's increment
// (depth 1) saves iterations and the extrapolation of the last two (depth 2) is exact; every
// warm-started step reaches the cold solve's answer within the tolerance.
TEST(FilmSolve, WarmStartFromTheLastStepsSavesIterations)
{
  const double dt = 1e-3;
  System s = random_system(5, 40, 150, 5, dt, 1e3, true);
  const std::vector<double> force_0 = s.force;
  FilmSolveOptions options;
  options.tolerance = 1e-10;
  options.max_iterations = 2000;
  const int n = int(s.velocity.size());
  std::vector<double> x(n), previous(n), cold(n);
  FilmSolver solver;
  int known = 0;
  for (int step = 0; step < 4; step++) {
    for (int e = 0; e < n; e++)
      s.force[e] = force_0[e] * (1.0 + 0.01 * step);
    options.warm_start = false;
    const FilmSolveResult from_zero = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt,
                                                   s.velocity.data(), s.force.data(), cold.data(), options);
    options.warm_start = film_increment_guess(x.data(), previous.data(), n, known);
    EXPECT_EQ(options.warm_start, step > 0);
    const FilmSolveResult warm = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(),
                                              s.force.data(), x.data(), options);
    ASSERT_TRUE(from_zero.converged && warm.converged);
    EXPECT_LT(relative_difference(x, cold), 1e-7) << step;
    if (known == 1) {
      EXPECT_LT(warm.iterations, from_zero.iterations * 3 / 4) << step;
    }
    if (known == 2) {
      EXPECT_LT(warm.iterations, from_zero.iterations / 4) << step;
    }
    std::printf("[ iterations ] step %d: cold %d, warm %d\n", step, from_zero.iterations, warm.iterations);
    known = std::min(known + 1, 2);
  }
}

// The preconditioner kept from the last solve (reuse_blocks) after the films changed by up to
// 10 %: the answer is the dense solve's, in about as many iterations as with fresh blocks; with
// fewer atoms than the kept blocks (another set of atoms) they are made again.
TEST(FilmSolve, KeptBlocksStillPrecondition)
{
  const double dt = 1e-3;
  System s = random_system(7, 40, 150, 5, dt, 1e3, true);
  FilmSolveOptions options;
  options.tolerance = 1e-12;
  options.max_iterations = 2000;
  std::vector<double> x(s.velocity.size());
  FilmSolver solver;
  solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(), s.force.data(), x.data(),
               options);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> change(0.9, 1.1);
  for (FilmLink &l : s.links)
    l.normal_damping *= change(rng), l.shear_damping *= change(rng);
  const FilmSolveResult fresh = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(),
                                             s.force.data(), x.data(), options);
  options.reuse_blocks = true;
  // The fresh blocks of the changed films are kept now; make the old ones current again.
  for (FilmLink &l : s.links)
    l.normal_damping *= 1.05;
  const FilmSolveResult unchanged = solver.solve(s.atoms(), s.links.data(), int(s.links.size()), dt, s.velocity.data(),
                                                 s.force.data(), x.data(), options);
  ASSERT_TRUE(fresh.converged && unchanged.converged);
  std::vector<double> w = x;
  for (size_t e = 0; e < w.size(); e++)
    w[e] += s.velocity[e];
  EXPECT_LT(relative_difference(w, dense_step(s, dt)), 1e-9);
  EXPECT_LE(unchanged.iterations, fresh.iterations + 5);
  std::printf("[ iterations ] fresh blocks %d, kept blocks after a 5 %% change %d\n", fresh.iterations,
              unchanged.iterations);
  System fewer = random_system(8, 20, 60, 2, dt, 1e3, true);
  std::vector<double> y(fewer.velocity.size());
  const FilmSolveResult other = solver.solve(fewer.atoms(), fewer.links.data(), int(fewer.links.size()), dt,
                                             fewer.velocity.data(), fewer.force.data(), y.data(), options);
  EXPECT_TRUE(other.converged);
  // Blocks made without the films of some atoms (or for another step) are made again: the
  // solve is a fresh solver's, iteration for iteration.
  System part = fewer;
  part.links.resize(10);
  solver.solve(part.atoms(), part.links.data(), int(part.links.size()), dt, part.velocity.data(), part.force.data(),
               y.data(), options);
  FilmSolver new_solver;
  options.reuse_blocks = false;
  const FilmSolveResult made = new_solver.solve(fewer.atoms(), fewer.links.data(), int(fewer.links.size()), dt,
                                                fewer.velocity.data(), fewer.force.data(), y.data(), options);
  options.reuse_blocks = true;
  const FilmSolveResult remade = solver.solve(fewer.atoms(), fewer.links.data(), int(fewer.links.size()), dt,
                                              fewer.velocity.data(), fewer.force.data(), y.data(), options);
  EXPECT_EQ(remade.iterations, made.iterations);
  const FilmSolveResult other_step = solver.solve(fewer.atoms(), fewer.links.data(), int(fewer.links.size()), 0.5 * dt,
                                                  fewer.velocity.data(), fewer.force.data(), y.data(), options);
  const FilmSolveResult other_step_made =
      new_solver.solve(fewer.atoms(), fewer.links.data(), int(fewer.links.size()), 0.5 * dt, fewer.velocity.data(),
                       fewer.force.data(), y.data(), options);
  EXPECT_EQ(other_step.iterations, other_step_made.iterations);
}

TEST(FilmSolve, VeryStiffFilmsStayFiniteAndStable)
{
  const double dt = 1e-3;
  for (unsigned seed = 1; seed <= 10; seed++) {
    System s = random_system(300 + seed, 20, 60, 4, dt, 1.0, false);
    for (FilmLink &l : s.links) {
      const double inverse_me = s.inverse_mass[l.i] + (l.j >= 0 ? s.inverse_mass[l.j] : 0.0) + 1e-3;
      l.normal_damping = l.shear_damping = 1e6 / (dt * inverse_me);
    }
    at_rest_outside(s);
    FilmSolveResult r;
    FilmSolveOptions options;
    options.tolerance = 1e-10;
    const std::vector<double> w = film_step(s, dt, &r, options);
    for (double v : w)
      ASSERT_TRUE(std::isfinite(v));
    EXPECT_TRUE(r.converged) << r.iterations;
    EXPECT_LE(kinetic_energy(s, w), kinetic_energy(s, s.velocity) * (1.0 + 1e-9));
  }
  // An isolated wall film at c dt / m = 1e6: u' = u / (1 + 1e6).
  System one;
  one.radius = {1.0}, one.inverse_mass = {0.5}, one.inverse_inertia = {1.25};
  one.velocity = {0.0, 0.0, -2.0, 0.0, 0.0, 0.0}, one.force.assign(6, 0.0);
  FilmLink l;
  l.normal = {0.0, 0.0, 1.0}, l.normal_damping = 1e6 * 2.0 / dt;
  one.links = {l};
  EXPECT_NEAR(film_step(one, dt)[2], -2.0 / (1.0 + 1e6), 1e-15 * 2.0);    // round-off of the increment -2
}

TEST(FilmSolve, IterationsWithinTheBoundFromTheLoads)
{
  // doc/film_solve.rst: A = I + dt M^-1 R has its spectrum in [1, 1 + max_i D_i], D_i the
  // budget's load with t_kick = dt (film_budget.h), so conjugate gradients in <,>_M need at most
  // ln(2 sqrt(kappa) / tol) / ln((sqrt(kappa) + 1) / (sqrt(kappa) - 1)) iterations.
  const double dt = 1e-3, tolerance = 1e-8;
  for (unsigned seed = 1; seed <= 10; seed++) {
    const System s = random_system(500 + seed, 40, 150, 8, dt, seed % 2 ? 10.0 : 1e3, true);
    std::vector<double> load(s.n(), 0.0);
    for (const FilmLink &l : s.links) {
      auto inverse_tangential = [&](int a) {
        return s.inverse_mass[a] + s.radius[a] * s.radius[a] * s.inverse_inertia[a];
      };
      const bool pair = l.j >= 0;
      const double a_n = l.normal_damping * dt * (s.inverse_mass[l.i] + (pair ? s.inverse_mass[l.j] : 0.0));
      const double a_t = l.shear_damping * dt * (inverse_tangential(l.i) + (pair ? inverse_tangential(l.j) : 0.0));
      load[l.i] += std::max(a_n, a_t);
      if (pair) load[l.j] += std::max(a_n, a_t);
    }
    const double root = std::sqrt(1.0 + *std::max_element(load.begin(), load.end()));
    const double bound = std::log(2.0 * root / tolerance) / std::log((root + 1.0) / (root - 1.0));
    FilmSolveOptions options;
    options.tolerance = tolerance;
    options.preconditioner = FilmPreconditioner::mass;
    FilmSolveResult plain, block;
    film_step(s, dt, &plain, options);
    options.preconditioner = FilmPreconditioner::block;
    film_step(s, dt, &block, options);
    std::printf("[ iterations ] 40 atoms, 158 films, max load %.3g: bound %.0f, mass-weighted CG %d, block-Jacobi "
                "%d\n",
                root * root - 1.0, std::ceil(bound), plain.iterations, block.iterations);
    EXPECT_TRUE(plain.converged);
    EXPECT_LE(plain.iterations, std::ceil(bound));
  }
}

TEST(FilmSolve, ExplicitFilmsOfUnloadedAtomsWithTheSolveNeverAddEnergy)
{
  // doc/film_solve.rst, "where each path is taken": films between atoms of load D <= 1 stay
  // explicit (their force at w in F), the films of atoms with D > 1 go into the solve.
  const double dt = 1e-3;
  size_t n_explicit = 0, n_implicit = 0;
  for (unsigned seed = 1; seed <= 30; seed++) {
    System s = random_system(700 + seed, 30, 25, 5, dt, 0.3, false);
    at_rest_outside(s);
    std::vector<double> load(s.n(), 0.0);
    auto share = [&](const FilmLink &l) {
      auto tangential = [&](int a) { return s.inverse_mass[a] + s.radius[a] * s.radius[a] * s.inverse_inertia[a]; };
      const bool pair = l.j >= 0;
      const double a_n = l.normal_damping * dt * (s.inverse_mass[l.i] + (pair ? s.inverse_mass[l.j] : 0.0));
      const double a_t = l.shear_damping * dt * (tangential(l.i) + (pair ? tangential(l.j) : 0.0));
      return std::max(a_n, a_t);
    };
    for (FilmLink &l : s.links) {    // each film within its own cap
      const double a = share(l);
      if (a > 1.0) l.normal_damping /= a, l.shear_damping /= a;
      load[l.i] += share(l);
      if (l.j >= 0) load[l.j] += share(l);
    }
    std::vector<FilmLink> explicit_films, implicit_films;
    for (const FilmLink &l : s.links)
      (load[l.i] <= 1.0 && (l.j < 0 || load[l.j] <= 1.0) ? explicit_films : implicit_films).push_back(l);
    System split = s;
    split.links = implicit_films;
    film_forces(s.atoms(), explicit_films.data(), int(explicit_films.size()), s.velocity.data(), false,
                split.force.data());
    const std::vector<double> w = film_step(split, dt);
    EXPECT_LE(kinetic_energy(s, w), kinetic_energy(s, s.velocity) * (1.0 + 1e-13)) << "seed " << seed;
    n_explicit += explicit_films.size(), n_implicit += implicit_films.size();
    if (seed == 30) std::printf("[ films ] explicit %zu, solved %zu\n", n_explicit, n_implicit);
  }
  EXPECT_GT(n_explicit, 100u);
  EXPECT_GT(n_implicit, 100u);
}
