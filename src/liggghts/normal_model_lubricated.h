// LIGGGHTS 3.8.0 normal contact model "lubricated": the spring-dashpot and lubrication film of
// the engine-free kernel (src/lubricated/), registered at run time by liblubricated_liggghts.so
// (lubricated_liggghts.cpp), so `pair_style gran model lubricated ...` and
// `fix wall/gran model lubricated ...` work with the stock liggghts binary.
//
// Mapping onto LIGGGHTS's contact interface (conventions of src/lubricated/normal_model.h):
//   en      unit normal from the partner (particle j, or the wall) to particle i;
//   gap     -deltan (LIGGGHTS's deltan is the overlap), u_n = vn (> 0 separating);
//   m_e     sidata.meff (reduced mass; the particle mass for a wall);
//   R       lubrication radius: 2 r_i r_j / (r_i + r_j) for a pair, r_i for a wall.
// The film acts before contact, where LIGGGHTS calls surfacesClose() without a normal: the
// model derives it from delta, sets has_force_update, and registers a contact distance
// factor that covers the film (and one step of approach, which the step-exact contact needs).
#pragma once

#ifdef NORMAL_MODEL
NORMAL_MODEL(LUBRICATED, lubricated, 42)
#else

#include "contact_models.h"
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_global.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include "liggghts/lubricated_properties.h"
#include "lubricated/normal_model.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace LIGGGHTS {
namespace ContactModels {

// Normal-model identifier: 6 bits, unused by the normal models of LIGGGHTS 3.8.0 (0-12).
static const int LUBRICATED = 42;

template <> class NormalModel<LUBRICATED> : public NormalModelBase {
 public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, ContactModelBase *cmb) :
      NormalModelBase(lmp, hsetup, cmb), is_wall_(cmb->is_wall())
  {
  }

  void registerSettings(Settings &) {}
  void postSettings(IContactHistorySetup *, ContactModelBase *) {}
  void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
  double stressStrainExponent() { return 1.0; }

  // Called at every run's init: read the properties, build the per-type-pair models.
  void connectToProperties(PropertyRegistry &)
  {
    const char *caller = is_wall_ ? "fix wall/gran model lubricated" : "pair gran model lubricated";
    ntypes_ = atom->ntypes;
    if (!atom->radius_flag || !atom->rmass_flag)
      error->all(FLERR, "model lubricated requires atom_style sphere (per-atom radius and rmass)");
    coefficients_ = lubricated::liggghts::read_coefficients(modify, ntypes_, caller, message_);
    if (!message_.empty()) fail(message_);
    build_models();

    // The film acts up to its reach beyond contact; the step-exact contact also needs one step
    // of approach before contact. LIGGGHTS calls surfacesClose() for gaps below
    // (factor - 1) (r_i + r_j) (pairs) or (factor - 1) r_i (walls).
    const double none = 1e300;
    double r_min = none;
    for (int i = 0; i < atom->nlocal; i++) r_min = std::min(r_min, atom->radius[i]);
    double r_min_all = none;
    MPI_Allreduce(&r_min, &r_min_all, 1, MPI_DOUBLE, MPI_MIN, world);
    const double reach = lubricated::liggghts::reach_fraction(coefficients_, ntypes_, is_wall_,
                                                              r_min_all < none ? r_min_all : 0.0);
    if (reach < 0.0)
      error->all(FLERR, "model lubricated: lubricatedGridSpacing needs the particles to exist "
                        "before the run (insert them first, or give lubricatedActivation)");
    neighbor->register_contact_dist_factor(1.0 + reach + lubricated::liggghts::approach_margin);
    warned_ = false;
  }

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces,
                                ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (update->dt != dt_) build_models();
    const int t = sidata.itype * (ntypes_ + 1) + sidata.jtype;
    const lubricated::NormalModel &model = models_[t];
    const double gap = -sidata.deltan, u_n = sidata.vn, m_e = sidata.meff;
    const double radius = is_wall_ ? sidata.radi
                                   : lubricated::lubrication_radius_pair(sidata.radi, sidata.radj);
    if (!update->setupflag && gap - u_n * dt_ >= (neighbor->contactDistanceFactor - 1.0) * sidata.radsum)
      missed_approach(u_n);    // entered from beyond the close range: no step before was seen
    const lubricated::NormalForce fn = lubricated::normal_force(model, gap, radius, m_e, u_n, evaluation());

    // Tangential and rolling models of LIGGGHTS read these: the solid contact force for the
    // Coulomb limit, and a tangential spring-dashpot with the normal period and restitution
    // for the tangential mass 2/7 m_e of spheres (src/lubricated/tangential.h; Costa et al.,
    // PRE 92, 053012, 2015): kt = 2/7 k [force/length], gammat = 2/7 c [mass/time].
    sidata.Fn = fn.contact;
    sidata.kn = m_e * model.contact.stiffness_per_mass;
    sidata.gamman = m_e * model.contact.damping_per_mass;
    sidata.kt = 2.0 / 7.0 * sidata.kn;
    sidata.gammat = 2.0 / 7.0 * sidata.gamman;

    apply(fn.total() * (is_wall_ ? sidata.area_ratio : 1.0), sidata.en, i_forces, j_forces);
  }

  // Near contact: the film, and the step-exact contact's first and last steps.
  inline void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces, ForceData &j_forces)
  {
    if (update->dt != dt_) build_models();
    const int t = scdata.itype * (ntypes_ + 1) + scdata.jtype;
    const lubricated::NormalModel &model = models_[t];
    const double r = std::sqrt(scdata.rsq);
    if (r <= 0.0) return;
    const double en[3] = {scdata.delta[0] / r, scdata.delta[1] / r, scdata.delta[2] / r};
    const double gap = r - scdata.radsum;
    const double *vi = scdata.v_i, *vj = scdata.v_j;
    const double u_n = (vi[0] - vj[0]) * en[0] + (vi[1] - vj[1]) * en[1] + (vi[2] - vj[2]) * en[2];
    const double radius = is_wall_ ? scdata.radi
                                   : lubricated::lubrication_radius_pair(scdata.radi, scdata.radj);
    if (!model.acts(gap, radius, u_n)) return;
    const double m_i = atom->rmass[scdata.i];
    const double m_e = is_wall_ ? m_i : lubricated::reduced_mass(m_i, atom->rmass[scdata.j]);
    const lubricated::NormalForce fn = lubricated::normal_force(model, gap, radius, m_e, u_n, evaluation());
    if (fn.total() == 0.0) return;
    if (scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;
    apply(fn.total() * (is_wall_ ? scdata.area_ratio : 1.0), en, i_forces, j_forces);
    scdata.has_force_update = true;
  }

 private:
  // LIGGGHTS integrates with velocity Verlet (fix nve/sphere).
  lubricated::Evaluation evaluation() const { return lubricated::evaluation_of(update->setupflag != 0, false); }

  // LIGGGHTS's Error::all throws with a pointer to the text, printed after the pair style (and
  // this model) are gone: the text must outlive them.
  void fail(const std::string &message)
  {
    static std::string text;
    text = message;
    error->all(FLERR, text.c_str());
  }

  void apply(double force, const double *en, ForceData &i_forces, ForceData &j_forces) const
  {
    for (int d = 0; d < 3; d++) {
      i_forces.delta_F[d] += force * en[d];
      if (!is_wall_) j_forces.delta_F[d] -= force * en[d];
    }
  }

  // k and c depend on the time step (N_c dt); rebuild whenever it changes.
  void build_models()
  {
    dt_ = update->dt;
    models_ = lubricated::liggghts::build_models(coefficients_, ntypes_, is_wall_, dt_, message_);
    if (!message_.empty()) fail(message_);
  }

  // A contact whose previous step was not evaluated: its entry is integrated approximately.
  void missed_approach(double u_n)
  {
    if (warned_) return;
    warned_ = true;
    message_ = lubricated::liggghts::missed_approach_warning(u_n, dt_, neighbor->contactDistanceFactor);
    error->warning(FLERR, message_.c_str());
  }

  bool is_wall_;
  bool warned_ = false;
  std::string message_;
  int ntypes_ = 0;
  double dt_ = -1.0;
  std::vector<lubricated::Coefficients> coefficients_;
  std::vector<lubricated::NormalModel> models_;
};

}    // namespace ContactModels
}    // namespace LIGGGHTS

#endif
