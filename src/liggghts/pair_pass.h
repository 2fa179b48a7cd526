// The pair style of `model lubricated` in LIGGGHTS: LIGGGHTS's Granular pair style with its
// pass over the neighbour list (compute_force) replaced, where nothing needs the general pass,
// by a leaner one with the same calls to the contact model in the same order, so the same
// forces to the bit.
//
// Why: LIGGGHTS's pass fills the whole pair record, resets both force records and tests a
// dozen options for every neighbour, and reaches x, v through double** (a dependent load per
// neighbour). The film of `model lubricated` widens LIGGGHTS's contact distance (the walls'
// film reach, twice a pair's: normal_model_lubricated.h), so about one neighbour in three lies
// beyond every model's reach and each close pair is only listed (close_pairs.h). This pass
// skips the pairs beyond the contact distance after their distance alone, and so the pairs
// without a contact flag beyond the normal model's reach over the step (its film's and both
// atoms' moves), for which every model's surfacesClose() does nothing, and it lists the other
// close pairs without a flag for the film loop from their distance and types alone (only the
// normal model acts on them); it reads the flat per-atom blocks. Every option the lean pass
// leaves out (energy or virial tallies, stored or summed contact forces, coupling, multicontact
// radii, non-spherical particles) makes it call LIGGGHTS's own pass instead.
#pragma once

#include "liggghts/normal_model_lubricated.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"
#include "liggghts/insert_stream_stub.h"
#include "pair_gran_base.h"
#undef FixInsertStream

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <string>

namespace lubricated {
namespace liggghts {

// LUBRICATED_LIGGGHTS_PASS: "lean" (or unset) or "liggghts" (LIGGGHTS's own pass everywhere);
// "" for another value.
inline std::string pass_requested()
{
  const char *value = std::getenv("LUBRICATED_LIGGGHTS_PASS");
  if (!value || std::strcmp(value, "lean") == 0) return "lean";
  return std::strcmp(value, "liggghts") == 0 ? "liggghts" : "";
}

// The GranStyle of a ContactModel (its surface, normal, cohesion, tangential and rolling models).
template <class CM> struct StyleOf;
template <class S> struct StyleOf<LIGGGHTS::ContactModels::ContactModel<S>> {
  using type = S;
};

template <class CM> class PairPass final : public LIGGGHTS::PairStyles::Granular<CM> {
  using Base = LIGGGHTS::PairStyles::Granular<CM>;

 public:
  PairPass(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, int64_t hash) :
      Base(lmp, parent, hash), lmp_(lmp), model_(*static_cast<CM *>(last_pair_contact_model())),
      normal_(*last_pair_normal_model()), lean_(pass_requested() == "lean")
  {
    normal_.keep_lambda_in_history(parent, parent->dnum_pair());
  }

  // At every run's init (the model reads its properties there): the pass a run takes, in the
  // log, and a bad LUBRICATED_LIGGGHTS_PASS refused.
  void init_granular() override
  {
    Base::init_granular();
    if (pass_requested().empty()) {
      // LIGGGHTS's Error::all throws with a pointer to the text, printed after the pair style is
      // gone: the text must outlive it.
      static std::string message;
      message = std::string("pair gran model lubricated: LUBRICATED_LIGGGHTS_PASS = '") +
                std::getenv("LUBRICATED_LIGGGHTS_PASS") + "' (expected lean or liggghts)";
      lmp_->error->all(FLERR, message.c_str());
    }
    if (lmp_->comm->me != 0) return;
    const char *line = lean_ ? "pair gran model lubricated: lean pair pass (LIGGGHTS's own where a per-pair "
                               "force is read; LUBRICATED_LIGGGHTS_PASS=liggghts for it everywhere)\n"
                             : "pair gran model lubricated: LIGGGHTS's own pair pass (LUBRICATED_LIGGGHTS_PASS)\n";
    if (lmp_->screen) fputs(line, lmp_->screen);
    if (lmp_->logfile) fputs(line, lmp_->logfile);
  }

  void compute_force(LAMMPS_NS::PairGran *pg, int eflag, int vflag, int addflag) override
  {
    if (eflag || vflag || !lean_ || !lean_pass_applies(pg)) {
      Base::compute_force(pg, eflag, vflag, addflag);
      return;
    }
    pg->evflag = pg->vflag_fdotr = 0;
    lean_pass(pg);
  }

 private:
  bool lean_pass_applies(LAMMPS_NS::PairGran *pg) const
  {
    const LAMMPS_NS::Atom *atom = lmp_->atom;
    return atom->rmass && !atom->shapetype_flag && !pg->storeSumDelta() && !pg->cpl() && !pg->storeContactForces() &&
           !pg->storeContactForcesStress() && !pg->store_sum_normal_force();
  }

  // What fill_overlap() reads of the atoms' masses: LIGGGHTS's rigid-body masses (nullptr: none),
  // its freeze group, and whether atoms are spheres (then the unit normal is given).
  struct PassMasses {
    const double *rmass, *rigid_mass;
    const int *mask;
    int freeze_bit;
    bool sphere;
  };

  // The overlap's data LIGGGHTS's pass gives surfacesIntersect(): the distance, the unit normal,
  // the masses (a rigid body's for its atoms; the partner's alone against a frozen atom) and the
  // spins. sidata holds the pair's delta and rsq.
  __attribute__((always_inline)) static void fill_overlap(LIGGGHTS::ContactModels::SurfacesIntersectData &sidata,
                                                          const PassMasses &masses, double *omega, int i, int j,
                                                          std::size_t j3)
  {
    const double r = std::sqrt(sidata.rsq), rinv = 1.0 / r;
    double mi = masses.rmass[i], mj = masses.rmass[j];
    if (masses.rigid_mass) {
      if (masses.rigid_mass[i] > 0.0) mi = masses.rigid_mass[i];
      if (masses.rigid_mass[j] > 0.0) mj = masses.rigid_mass[j];
    }
    double meff = mi * mj / (mi + mj);
    if (masses.mask[i] & masses.freeze_bit) meff = mj;
    if (masses.mask[j] & masses.freeze_bit) meff = mi;
    sidata.r = r;
    sidata.rinv = rinv;
    sidata.meff = meff;
    sidata.mi = mi;
    sidata.mj = mj;
    if (masses.sphere) {
      sidata.en[0] = sidata.delta[0] * rinv;
      sidata.en[1] = sidata.delta[1] * rinv;
      sidata.en[2] = sidata.delta[2] * rinv;
    }
    sidata.omega_i = omega + 3 * i;
    sidata.omega_j = omega + j3;
  }

  // LIGGGHTS's pass (pair_gran_base.h) without the options lean_pass_applies() excludes.
  void lean_pass(LAMMPS_NS::PairGran *pg)
  {
    using namespace LIGGGHTS::ContactModels;
    LAMMPS_NS::Atom *atom = lmp_->atom;
    const double *x = atom->x[0], *radius = atom->radius, *rmass = atom->rmass;
    // v and omega as the blocks they are (3 per atom): a row pointer per neighbour is a dependent
    // load, which misses the cache in large beds.
    double *v = atom->v[0], *omega = atom->omega[0];
    double *f = atom->f[0], *torque = atom->torque[0];
    const int *type = atom->type, *mask = atom->mask;
    const int nlocal = atom->nlocal, newton_pair = lmp_->force->newton_pair;
    const LAMMPS_NS::NeighList *list = pg->list;
    int **first_flags = pg->listgranhistory ? pg->listgranhistory->firstneigh : nullptr;
    double **first_history = pg->listgranhistory ? pg->listgranhistory->firstdouble : nullptr;
    const int dnum = pg->dnum();
    const PassMasses masses{rmass, pg->fr_pair() ? pg->mr_pair() : nullptr, mask, pg->freeze_group_bit(),
                            atom->sphere_flag != 0};
    const double factor = lmp_->neighbor->contactDistanceFactor;

    SurfacesIntersectData sidata;    // zeroed as LIGGGHTS's pass zeroes its own
    std::memset(static_cast<void *>(&sidata), 0, sizeof(sidata));
    sidata.area_ratio = 1.0;
    ForceData i_forces, j_forces;
    sidata.computeflag = pg->computeflag();
    sidata.shearupdate = pg->shearupdate();
    model_.beginPass(sidata, i_forces, j_forces);
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2], radi = radius[i];
      int *flags = first_flags ? first_flags[i] : nullptr;
      double *history = first_history ? first_history[i] : nullptr;
      const int *jlist = list->firstneigh[i];
      const int jnum = list->numneigh[i];
      sidata.i = i;
      sidata.radi = radi;
      for (int jj = 0; jj < jnum; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        const std::size_t j3 = 3 * static_cast<std::size_t>(j);    // no sign extension per entry
        const double delx = xi - x[j3], dely = yi - x[j3 + 1], delz = zi - x[j3 + 2];
        const double rsq = delx * delx + dely * dely + delz * delz;
        const double radj = radius[j], radsum = radi + radj;
        // Beyond the contact distance LIGGGHTS's pass calls no model: nothing to do. Nor for a
        // pair without a contact flag beyond the normal model's reach over the step (idle_reach),
        // whose models' surfacesClose() would do nothing (idle_close_pairs): one test, its
        // distance chosen by the flag.
        const double wide = factor * radsum;
        const bool flagless = idle_close_pairs && (!flags || flags[jj] == 0);
        const double outer = flagless ? std::min(wide, normal_.idle_reach(radsum)) : wide;
        if (!(rsq < outer * outer)) continue;
        // A close pair apart without a contact flag (within idle_reach: outer above): only the normal
        // model acts (idle_close_pairs), most often by listing it, from its data alone (no pair
        // record to fill).
        if (flagless && !(rsq < radsum * radsum) && normal_.list_close_pair(i, j, type[i], type[j])) continue;
        sidata.radj = radj;
        sidata.j = j;
        sidata.delta[0] = delx;
        sidata.delta[1] = dely;
        sidata.delta[2] = delz;
        sidata.rsq = rsq;
        sidata.radsum = radsum;
        sidata.contact_flags = flags ? &flags[jj] : nullptr;
        sidata.contact_history = history ? &history[dnum * jj] : nullptr;
        sidata.v_i = v + 3 * i;
        sidata.v_j = v + j3;
        sidata.itype = type[i];
        sidata.jtype = type[j];
        i_forces.reset();
        j_forces.reset();
        if (rsq < radsum * radsum && model_.checkSurfaceIntersect(sidata)) {
          fill_overlap(sidata, masses, omega, i, j, j3);
          model_.surfacesIntersect(sidata, i_forces, j_forces);
          model_.endSurfacesIntersect(sidata, nullptr, i_forces, j_forces);
          sidata.has_force_update = true;
        } else {
          sidata.has_force_update = false;
          model_.surfacesClose(sidata, i_forces, j_forces);
        }
        if (!sidata.has_force_update || !sidata.computeflag) continue;
        add_forces(pg->relax(i), f + 3 * i, torque + 3 * i, i_forces);
        if (newton_pair || j < nlocal) add_forces(pg->relax(j), f + j3, torque + j3, j_forces);
      }
    }
    model_.endPass(sidata, i_forces, j_forces);
  }

  static void add_forces(double relax, double *f, double *torque, const LIGGGHTS::ContactModels::ForceData &forces)
  {
    for (int d = 0; d < 3; d++) {
      f[d] += relax * forces.delta_F[d];
      torque[d] += relax * forces.delta_torque[d];
    }
  }

  // Whether every model but the normal one does nothing in surfacesClose() for a pair without
  // a contact flag: the default surface model, no cohesion, no rolling resistance, and a
  // tangential model that is off or only clears its flag and zeroes its history there (a flag
  // of 0 means the tangential history of the pair is zero: the models set a flag with any history
  // and clear both together, and a neighbour build restores a history with its flag; the normal
  // model's lambda(eps_al), keyed by eps_al, holds whatever the flag).
  using Style = typename StyleOf<CM>::type;
  static constexpr bool idle_close_pairs = Style::SURFACE == LIGGGHTS::ContactModels::SURFACE_DEFAULT &&
                                           Style::COHESION == LIGGGHTS::ContactModels::COHESION_OFF &&
                                           Style::ROLLING == LIGGGHTS::ContactModels::ROLLING_OFF &&
                                           (Style::TANGENTIAL == LIGGGHTS::ContactModels::TANGENTIAL_OFF ||
                                            Style::TANGENTIAL == LIGGGHTS::ContactModels::TANGENTIAL_NO_HISTORY ||
                                            Style::TANGENTIAL == LIGGGHTS::ContactModels::TANGENTIAL_HISTORY);

  LAMMPS_NS::LAMMPS *lmp_;
  CM &model_;
  LIGGGHTS::ContactModels::NormalModel<LIGGGHTS::ContactModels::LUBRICATED> &normal_;
  const bool lean_;    // false: always LIGGGHTS's pass (LUBRICATED_LIGGGHTS_PASS=liggghts)
};

}    // namespace liggghts
}    // namespace lubricated
