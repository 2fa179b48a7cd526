// The pairs LIGGGHTS's pair loop finds close (within its contact distance, not in overlap) in
// one step of `model lubricated`: listed by surfacesClose() and evaluated together, in pieces of
// the pass (each piece while its atoms are still in the cache; the last at endPass), in one loop
// without branches or calls, which the compiler vectorises, as the LAMMPS pair style's film
// loops do (src/pair_lubricated_springdashpot/vector_pairs.h).
//
// LIGGGHTS calls surfacesClose() for every pair within contactDistanceFactor (r_i + r_j); that
// factor is the largest any model registers, the walls' (their film reaches 0.75 dx of the
// smallest radius, twice a pair's fraction): in a dense bed most neighbours are close pairs,
// and most of those are in the film and apart over the step. The loop gives, per pair, whether
// the model acts (film reach, or a contact within a step: NormalModel::acts) and, where it acts
// and the pair stays apart over the step, the film force of normal_model.h film_force_apart();
// the rest (a contact may start within the step) take normal_force() one by one.
#pragma once

#include "lubricated/normal_model.h"
#include "lubricated/pair_geometry.h"

#include <algorithm>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class PairGran;
}    // namespace LAMMPS_NS

namespace lubricated {
namespace liggghts {

// The two common cases of a step (stepping: a step's evaluation, not a set-up's) in the closed
// forms of the kernel (normal_model.h), those of the LAMMPS pair style's vectorised loops,
// equal to normal_force() within rounding: a contact in overlap now and a step ago (and, by the
// oscillator, a step ahead), whose film is saturated (no logarithm of the gap); and a pair apart
// over the whole step, where no contact can act (the film alone). False where they do not
// apply: normal_force() then. sustained_contact: for an exact model in a step only (the caller
// tests that first: lambda_al, lambda(eps_al) of the pair, is only needed there).
inline bool sustained_contact(const NormalModel &model, double gap, const FilmRadius &radius, double m_e, double u_n,
                              NormalForce &fn, double lambda_al)
{
  bool sustained = false;
  fn = sustained_contact_force(model, gap, radius, m_e, u_n, lambda_al, sustained);
  return sustained;
}

inline bool film_apart(const NormalModel &model, double gap, const FilmRadius &radius, double m_e, double u_n,
                       bool stepping, NormalForce &fn)
{
  if (!model.exact || !stepping || !model.lubrication.active() || contact_possible(gap, u_n, model.step.dt))
    return false;
  const Lubrication &lub = model.lubrication;
  const double dt = model.step.dt, inv_dt = model.step.inv_dt;
  fn.lubrication = lub.grid_spacing > 0.0 ? film_force_apart<true>(lub, gap, radius, m_e, u_n, dt, inv_dt)
                                          : film_force_apart<false>(lub, gap, radius, m_e, u_n, dt, inv_dt);
  return true;
}

struct ClosePairs {
  // Per pair, from evaluate(): FilmPairState (lubricated/film_only_loop.h); the film force on i
  // (3 components) [force], its value along n [force] where film_pair_apart; the film's capacity
  // m_e |u_n| [momentum].
  std::vector<int> state;
  std::vector<double> force_x, force_y, force_z, film, capacity;

  void clear() { count_ = 0; }
  // One test per pair (surfacesClose() lists every close pair of a pass; GCC left it a call).
  __attribute__((always_inline)) void add(int atom_i, int atom_j)
  {
    if (count_ == static_cast<int>(i_.size())) grow();
    i_[count_] = atom_i;
    j_[count_] = atom_j;
    count_++;
  }
  int size() const { return count_; }

  // A step (velocities are v^(n-1/2)) of the exact model `model` (exact contact, active film) for
  // every listed pair, reduced masses m_i m_j / (m_i + m_j) (no rigid body, no held atom).
  void evaluate(const PairAtoms &atoms, const NormalModel &model);

  // evaluate(), then each force applied as LIGGGHTS applies a pair's (its relax factor; j's
  // share where newton_pair or j is owned), and each film recorded in the film budget (budget:
  // nullptr, none); no contact flag is set (a pair apart has no history: surfacesClose). The
  // few pairs that may touch within the step take normal_force().
  void apply(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *pair, const NormalModel &model,
             class FixLubricatedFilmBudget *budget);

 private:
  __attribute__((noinline)) void grow()
  {
    const size_t size = std::max<size_t>(1024, 2 * i_.size());
    i_.resize(size);
    j_.resize(size);
  }
  int count_ = 0;
  std::vector<int> i_, j_;
  std::vector<int> general_;    // apply(): the places of the general pairs
};

}    // namespace liggghts
}    // namespace lubricated
