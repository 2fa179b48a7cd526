/* ----------------------------------------------------------------------
   Film force of pairs that stay apart over a step (see film_only_pairs.h)
------------------------------------------------------------------------- */

#include "film_only_pairs.h"

#include "lubricated/normal_model.h"

#include <cmath>

namespace lub = lubricated;

// x86-64-v3 (AVX2) and v4 (AVX-512) have the gathers the loop needs; elsewhere it runs scalar.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#define FILM_ONLY_PAIRS_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define FILM_ONLY_PAIRS_CLONES
#endif

namespace LAMMPS_NS {
namespace film_only_pairs {

  template <bool GRID>
  __attribute__((always_inline)) static inline void loop(const Atoms &atoms, const lub::Lubrication &film,
                                                         double dt, const int *__restrict pair_i,
                                                         const int *__restrict pair_j, int n,
                                                         double *__restrict fpair)
  {
    const double *__restrict x = atoms.x;
    const double *__restrict v = atoms.v;
    const double *__restrict radius = atoms.radius;
    const double *__restrict rmass = atoms.rmass;
    const lub::Lubrication lubrication = film;    // a local copy: invariant to the compiler
    const double inv_dt = 1.0 / dt;
    for (int c = 0; c < n; c++) {
      const int i = pair_i[c], j = pair_j[c];
      const double delx = x[3 * i] - x[3 * j];
      const double dely = x[3 * i + 1] - x[3 * j + 1];
      const double delz = x[3 * i + 2] - x[3 * j + 2];
      const double dvx = v[3 * i] - v[3 * j];
      const double dvy = v[3 * i + 1] - v[3 * j + 1];
      const double dvz = v[3 * i + 2] - v[3 * j + 2];
      const double r = std::sqrt(delx * delx + dely * dely + delz * delz);
      const double rinv = 1.0 / r;
      const double u_n = (dvx * delx + dvy * dely + dvz * delz) * rinv;
      const double radi = radius[i], radj = radius[j];
      const double m_e = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
      fpair[c] = lub::film_force_apart<GRID>(lubrication, r - (radi + radj), lub::film_radius_pair(radi, radj),
                                             m_e, u_n, dt, inv_dt) * rinv;
    }
  }

  FILM_ONLY_PAIRS_CLONES
  void forces(const Atoms &atoms, const lub::Lubrication &film, double dt, const int *pair_i,
              const int *pair_j, int n, double *fpair)
  {
    if (film.grid_spacing > 0.0) loop<true>(atoms, film, dt, pair_i, pair_j, n, fpair);
    else loop<false>(atoms, film, dt, pair_i, pair_j, n, fpair);
  }

}    // namespace film_only_pairs
}    // namespace LAMMPS_NS
