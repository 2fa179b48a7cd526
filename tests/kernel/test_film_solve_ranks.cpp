// The coupled film solve (lubricated/film_solve.h) split over two "ranks" with ghosts (the
// forward, reverse and sum callbacks), and its block-Jacobi preconditioner on an ill-conditioned
// chain.
#include "film_solve_systems.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

using namespace film_solve_test;

namespace {

// Two "ranks" as two threads, each with its owned atoms first and copies of the other's atoms
// as ghosts; forward, reverse and sum through shared slots between barriers.
class Barrier {
 public:
  void wait()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    const int generation = generation_;
    if (++arrived_ == 2) {
      arrived_ = 0, generation_++;
      changed_.notify_all();
    } else {
      changed_.wait(lock, [&] { return generation_ != generation; });
    }
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  int arrived_ = 0, generation_ = 0;
};

struct Rank {
  System local;    // owned atoms first, then ghosts
  int owned = 0;
  std::vector<int> global;                      // local index -> global atom
  std::vector<int> ghost_owner;                 // ghost g (from owned) -> the other rank's local index
  std::vector<std::pair<int, int>> received;    // (the other rank's ghost, my owned atom)
  std::vector<double> increment;
  FilmSolveResult result;
};

struct Exchange {
  Barrier barrier;
  double *data[2] = {nullptr, nullptr};
  double values[2][4] = {};
};

Rank make_rank(const System &s, int rank, int split)
{
  Rank r;
  std::vector<int> local(s.n(), -1);
  auto add = [&](int a) {
    if (local[a] >= 0) return;
    local[a] = int(r.global.size());
    r.global.push_back(a);
  };
  for (int a = 0; a < s.n(); a++)
    if ((a < split) == (rank == 0)) add(a);
  r.owned = int(r.global.size());
  for (size_t k = rank; k < s.links.size(); k += 2) {    // each film on one rank, alternately
    add(s.links[k].i);
    if (s.links[k].j >= 0) add(s.links[k].j);
    FilmLink l = s.links[k];
    l.i = local[l.i];
    if (l.j >= 0) l.j = local[l.j];
    r.local.links.push_back(l);
  }
  for (int a : r.global) {
    r.local.radius.push_back(s.radius[a]);
    r.local.inverse_mass.push_back(s.inverse_mass[a]);
    r.local.inverse_inertia.push_back(s.inverse_inertia[a]);
    for (int d = 0; d < film_dofs; d++) {
      r.local.velocity.push_back(s.velocity[6 * a + d]);
      r.local.force.push_back(s.force[6 * a + d]);
    }
  }
  for (size_t g = r.owned; g < r.global.size(); g++) {
    const int a = r.global[g];    // the other rank's owned atoms are numbered in global order
    r.ghost_owner.push_back(rank == 0 ? a - split : a);
  }
  return r;
}

void solve_rank(Rank &r, int rank, Exchange &x, double dt)
{
  Rank &me = r;
  const int other = 1 - rank;
  FilmComm comm;
  comm.forward = [&](double *data, int per) {
    x.data[rank] = data;
    x.barrier.wait();
    for (size_t g = 0; g < me.ghost_owner.size(); g++)
      for (int d = 0; d < per; d++)
        data[per * (me.owned + g) + d] = x.data[other][per * me.ghost_owner[g] + d];
    x.barrier.wait();
  };
  comm.reverse = [&](double *data, int per) {
    x.data[rank] = data;
    x.barrier.wait();
    for (const auto &[ghost, atom] : me.received)
      for (int d = 0; d < per; d++)
        data[per * atom + d] += x.data[other][per * ghost + d];
    x.barrier.wait();
  };
  comm.sum = [&](double *values, int count) {
    std::copy(values, values + count, x.values[rank]);
    x.barrier.wait();
    for (int c = 0; c < count; c++)
      values[c] = x.values[0][c] + x.values[1][c];
    x.barrier.wait();
  };
  FilmAtoms atoms = r.local.atoms();
  atoms.owned = r.owned;
  me.increment.assign(r.local.velocity.size(), 0.0);
  FilmSolveOptions options;
  options.tolerance = 1e-13;
  options.max_iterations = 2000;
  FilmSolver solver;
  me.result = solver.solve(atoms, r.local.links.data(), int(r.local.links.size()), dt, r.local.velocity.data(),
                           r.local.force.data(), me.increment.data(), options, comm);
}

}    // namespace

TEST(FilmSolve, TwoRanksWithGhostsMatchOneRank)
{
  const double dt = 1e-3;
  const System s = random_system(11, 24, 60, 6, dt, 50.0, true);
  const std::vector<double> single = film_step(s, dt);
  Rank ranks[2] = {make_rank(s, 0, 11), make_rank(s, 1, 11)};
  ASSERT_GT(ranks[0].ghost_owner.size(), 0u);
  ASSERT_GT(ranks[1].ghost_owner.size(), 0u);
  for (int rank = 0; rank < 2; rank++)
    for (size_t g = 0; g < ranks[rank].ghost_owner.size(); g++)
      ranks[1 - rank].received.push_back({ranks[rank].owned + int(g), ranks[rank].ghost_owner[g]});
  Exchange exchange;
  std::thread threads[2];
  for (int rank = 0; rank < 2; rank++)
    threads[rank] = std::thread([&, rank] { solve_rank(ranks[rank], rank, exchange, dt); });
  for (auto &t : threads)
    t.join();
  std::vector<double> split(single.size(), 0.0);
  for (int rank = 0; rank < 2; rank++) {
    const Rank &r = ranks[rank];
    EXPECT_TRUE(r.result.converged);
    EXPECT_EQ(r.result.iterations, ranks[0].result.iterations);
    for (size_t a = 0; a < r.global.size(); a++)
      for (int d = 0; d < film_dofs; d++) {
        const double value = r.local.velocity[6 * a + d] + r.increment[6 * a + d];
        if (int(a) < r.owned)
          split[6 * r.global[a] + d] = value;
        else
          EXPECT_NEAR(value, single[6 * r.global[a] + d], 1e-10) << "ghost after the final forward";
      }
  }
  EXPECT_LT(relative_difference(split, single), 1e-10);
}

TEST(FilmSolve, BlockPreconditionerCutsIterationsOnAnIllConditionedChain)
{
  // A chain of spheres alternating radius 1 and 0.1 (masses 1000 apart), films of shares
  // c dt / m_e from 1e-2 to 1e4, one end on a wall.
  const double dt = 1e-3;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  System s;
  const int n = 60;
  for (int i = 0; i < n; i++) {
    const double r = i % 2 ? 0.1 : 1.0, m = 4.18879 * r * r * r;
    s.radius.push_back(r);
    s.inverse_mass.push_back(1.0 / m);
    s.inverse_inertia.push_back(1.0 / sphere_inertia(m, r));
    for (int d = 0; d < film_dofs; d++)
      s.velocity.push_back(u(rng) - 0.5), s.force.push_back(0.0);
  }
  for (int i = 0; i < n; i++) {
    FilmLink l;
    l.i = i, l.j = i - 1;
    l.normal = i ? random_unit(rng) : Vec3{0.0, 0.0, 1.0};
    const double inverse_me = s.inverse_mass[i] + (i ? s.inverse_mass[i - 1] : 0.0);
    l.normal_damping = std::pow(10.0, -2.0 + 6.0 * u(rng)) / (dt * inverse_me);
    l.shear_damping = std::pow(10.0, -2.0 + 6.0 * u(rng)) / (dt * inverse_me);
    s.links.push_back(l);
  }
  FilmSolveResult plain, block;
  FilmSolveOptions options;
  options.tolerance = 1e-8;
  options.preconditioner = FilmPreconditioner::mass;
  const std::vector<double> w_plain = film_step(s, dt, &plain, options);
  options.preconditioner = FilmPreconditioner::block;
  const std::vector<double> w_block = film_step(s, dt, &block, options);
  std::printf("[ iterations ] chain of %d: mass-weighted CG %d, block-Jacobi %d (tolerance 1e-8)\n", n,
              plain.iterations, block.iterations);
  EXPECT_TRUE(plain.converged);
  EXPECT_TRUE(block.converged);
  EXPECT_LT(block.iterations, plain.iterations);
  EXPECT_LT(relative_difference(w_block, dense_step(s, dt)), 1e-6);
}
