// LIGGGHTS 3.8.0 normal contact model "lubricated": the spring-dashpot and lubrication film of
// the engine-free kernel (src/lubricated/), registered at run time by liblubricated_liggghts.so
// (lubricated_liggghts.cpp), so `pair_style gran model lubricated ...` and
// `fix wall/gran model lubricated ...` work with the stock liggghts binary.
//
// Mapping onto LIGGGHTS's contact interface (conventions of src/lubricated/normal_model.h):
//   en      unit normal from the partner (particle j, or the wall) to particle i;
//   gap     -deltan (LIGGGHTS's deltan is the overlap), u_n = vn (> 0 separating);
//   m_e     the mass the contact moves, in overlap and near it: the reduced mass (a rigid body's
//           mass for its atoms, as LIGGGHTS's sidata.meff), the mover's mass alone against an
//           atom left out of every integrator or held by fix freeze, fix move or
//           fix setforce 0 0 0; a wall's meff;
//   R       lubrication radius: 2 r_i r_j / (r_i + r_j) for a pair, r_i for a wall.
// The film acts before contact, where LIGGGHTS calls surfacesClose() without a normal: the
// model derives it from delta, sets has_force_update, and registers a contact distance
// factor that covers the film (and one step of approach, which the step-exact contact needs).
// Every film also enters the many-body film budget (fix_lubricated_film_budget.h), which the
// pair's model creates; walls join it when a pair model lubricated exists. A step evaluates
// sustained contacts and pairs apart over the step in the kernel's closed forms, and lists the
// pair's close pairs for a vectorised loop, run in pieces while their atoms are in the cache
// (close_pairs.h).
#pragma once

#ifdef NORMAL_MODEL
NORMAL_MODEL(LUBRICATED, lubricated, 42)
#else

#include "contact_models.h"
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_global.h"
#include "fix_wall_gran.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"
#include "update.h"

#include "liggghts/close_pairs.h"
#include "liggghts/fix_lubricated_film_budget.h"
#include "liggghts/fix_lubricated_step_velocity.h"
#include "liggghts/lubricated_properties.h"
#include "liggghts/setforce_holds.h"
#include "lubricated/check_setup.h"
#include "lubricated/contact.h"
#include "lubricated/contact_network.h"
#include "lubricated/film_budget.h"
#include "lubricated/normal_model.h"
#include "lubricated/overlap_check.h"
#include "lubricated/tangential.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace LIGGGHTS {
namespace ContactModels {
template <int> class NormalModel;
static const int LUBRICATED = 42;    // normal-model identifier: 6 bits, unused by LIGGGHTS 3.8.0's (0-12)
}    // namespace ContactModels
}    // namespace LIGGGHTS

namespace lubricated {
namespace liggghts {
// The ContactModel that LIGGGHTS's Granular pair style keeps private, and its normal model
// (pair_pass.h reaches them through these): a pair's normal model records itself and its parent,
// the ContactModel being built, in its constructor, which runs inside Granular's.
void note_pair_contact_model(LIGGGHTS::ContactModels::ContactModelBase *model,
                             LIGGGHTS::ContactModels::NormalModel<LIGGGHTS::ContactModels::LUBRICATED> *normal);
LIGGGHTS::ContactModels::ContactModelBase *last_pair_contact_model();
LIGGGHTS::ContactModels::NormalModel<LIGGGHTS::ContactModels::LUBRICATED> *last_pair_normal_model();
}    // namespace liggghts
}    // namespace lubricated

namespace LIGGGHTS {
namespace ContactModels {

template <> class NormalModel<LUBRICATED> : public NormalModelBase {
 public:
  NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, ContactModelBase *cmb) :
      NormalModelBase(lmp, hsetup, cmb), is_wall_(cmb->is_wall()),
      pair_(is_wall_ ? nullptr : static_cast<LAMMPS_NS::PairGran *>(hsetup)), hsetup_(hsetup)
  {
    if (!is_wall_) lubricated::liggghts::note_pair_contact_model(cmb, this);
  }
  ~NormalModel() { lubricated::liggghts::forget_radius(this); }

  void registerSettings(Settings &) {}
  void postSettings(IContactHistorySetup *, ContactModelBase *) {}

  // A pair whose contacts keep a history (LIGGGHTS's tangential model's) keeps lambda(eps_al) of
  // each contact's film in it too (history_lambda); without one none is made (it would cost every
  // pair a history). Called by the pair's pass (pair_pass.h) once its models are built, as for a
  // pair style read from a restart file (which calls no postSettings), with the history values
  // registered so far.
  void keep_lambda_in_history(IContactHistorySetup *hsetup, int history_values);

  void beginPass(SurfacesIntersectData &sidata, ForceData &, ForceData &);
  void endPass(SurfacesIntersectData &, ForceData &, ForceData &)
  {
    if (close_.size() > 0) apply_close_pairs();
  }
  double stressStrainExponent() { return 1.0; }

  // Called at every run's init: read the properties, build the per-type-pair models.
  void connectToProperties(PropertyRegistry &);

  inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
  {
    if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
    if (update->dt != dt_) build_models();
    const int t = sidata.itype * (ntypes_ + 1) + sidata.jtype;
    const lubricated::NormalModel &model = models_[t];
    const bool continued = step_velocity_->continues();
    const double gap = -sidata.deltan,
                 u_n = continued ? sidata.vn - step_velocity_->kick_along(sidata.i, partner(sidata), sidata.en)
                                 : sidata.vn;
    const double m_e = is_wall_ ? sidata.meff : pair_reduced_mass(sidata.i, sidata.j);
    const lubricated::FilmRadius radius = film_radius(sidata);
    if (!update->setupflag && gap - u_n * dt_ >= (neighbor->contactDistanceFactor - 1.0) * sidata.radsum)
      missed_approach(u_n);    // entered from beyond the close range: no step before was seen
    if (gap < -overlap_depth_ * smaller_radius(sidata)) check_overlap(sidata, gap, t);
    lubricated::NormalForce fn;
    if (!(model.exact && stepping(continued) &&
          lubricated::liggghts::sustained_contact(model, gap, radius, m_e, u_n, fn,
                                                  history_lambda(model.lubrication, radius, sidata.contact_history))))
      fn = lubricated::normal_force(model, gap, radius, m_e, u_n, evaluation(continued));

    // Tangential and rolling models of LIGGGHTS read these: the solid contact force for the
    // Coulomb limit, and a tangential spring-dashpot with the normal period and restitution
    // for the tangential mass 2/7 m_e of spheres (src/lubricated/tangential.h; Costa et al.,
    // PRE 92, 053012, 2015): kt = 2/7 k [force/length], gammat = 2/7 c [mass/time].
    sidata.Fn = fn.contact;
    sidata.kn = m_e * model.contact.stiffness_per_mass;
    sidata.gamman = m_e * model.contact.damping_per_mass;
    sidata.kt = lubricated::tangential_mass_ratio * sidata.kn;
    sidata.gammat = lubricated::tangential_mass_ratio * sidata.gamman;

    apply(fn.total() * (is_wall_ ? sidata.area_ratio : 1.0), sidata.en, i_forces, j_forces);
    if (fn.lubrication != 0.0 && budget_on_ && budget_->active())
      record_film(sidata, fn.lubrication * (is_wall_ ? sidata.area_ratio : 1.0), sidata.en, m_e, u_n, continued);
    // In overlap a step ago too: a sustained contact of the network check.
    if (!is_wall_ && budget_ && budget_->network_due() && budget_->network_load_matters(t) && gap - u_n * dt_ < 0.0) {
      double m_i, m_j;
      contact_masses(sidata, m_i, m_j);
      if (std::isfinite(m_i) || std::isfinite(m_j))
        budget_->add_network_contact(sidata.i, sidata.j, t, sidata.en, m_e, m_i, m_j);
    }
  }

  // A pair apart (rsq >= radsum^2) beyond idle_reach(radsum) can act in no type pair's model
  // within the coming step, so surfacesClose() does nothing for it: it is not listed, and the
  // lean pass (pair_pass.h) skips it where no contact flag asks LIGGGHTS's models to reset it.
  // Both passes thus list the same pairs and apply the same pieces.
  __attribute__((always_inline)) double idle_reach(double radsum) const { return radsum * idle_scale_ + idle_offset_; }

  // surfacesClose()'s listing of a pair within idle_reach, from the pair's data alone: true where
  // it is listed for the close-pair loop, false where surfacesClose() evaluates it itself. The
  // lean pass (pair_pass.h), which has tested idle_reach already, calls it alone for a close pair
  // without a contact flag, for which every other model's surfacesClose() does nothing.
  __attribute__((always_inline)) bool list_close_pair(int i, int j, int itype, int jtype)
  {
    const int t = itype * (ntypes_ + 1) + jtype;
    if (!(defer_close_ && (t == close_type_ || first_close_type(t)))) return false;
    close_.add(i, j);
    if (close_.size() == close_piece) apply_close_pairs();
    return true;
  }

  // Near contact: the film, and the step-exact contact's first and last steps. LIGGGHTS calls
  // this for every pair within its contact distance, which the walls' film sets (reach 0.75 dx
  // of the smallest radius; about five pairs per sphere and step): in a step the pair's are
  // listed for the vectorised loop, run for every close_piece of them (close_pairs.h). The
  // listing and the test that most pairs fail are inlined into the pair's pass (GCC left them a
  // call, a large part of an active bed's time), the rest is a call.
  // A pair apart holds no history of this model (lambda(eps_al) is kept for contacts in overlap),
  // so its flag is cleared, as the tangential model clears its own: LIGGGHTS then keeps no
  // partner record for a film, and the lean pass takes the pair as one without a flag. A flag
  // left set by every film made nearly all close pairs of a wet bed flagged, each re-stored at
  // every neighbour build and visited in full by the pass.
  // A wall's history is LIGGGHTS's per-atom wall history: its flag is left as LIGGGHTS's models do.
  __attribute__((always_inline)) inline void surfacesClose(SurfacesCloseData &scdata, ForceData &i_forces,
                                                           ForceData &j_forces)
  {
    if (!is_wall_ && scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
    const double idle = idle_reach(scdata.radsum);
    if (!(scdata.rsq < idle * idle) || list_close_pair(scdata.i, scdata.j, scdata.itype, scdata.jtype)) return;
    const int t = scdata.itype * (ntypes_ + 1) + scdata.jtype;
    if (update->dt != dt_) build_models();
    if (!(scdata.rsq > 0.0)) return;
    // Most close pairs are out of the film and a step away from contact: known without the square
    // root (a continued run's kick changes u_n: the whole test there).
    const double *vi = scdata.v_i, *vj = scdata.v_j;
    const double dv_dot_del =
        (vi[0] - vj[0]) * scdata.delta[0] + (vi[1] - vj[1]) * scdata.delta[1] + (vi[2] - vj[2]) * scdata.delta[2];
    if (!models_[t].may_act(scdata.rsq, dv_dot_del, scdata.radsum) && !step_velocity_->continues()) return;
    close_pair_acts(scdata, models_[t], i_forces, j_forces);
  }

 private:
  // The close pairs listed so far, evaluated and applied while their atoms are still in the cache
  // (a piece of the pass; the film budget takes its records at the step's end).
  static constexpr int close_piece = 1024;
  __attribute__((noinline)) void apply_close_pairs();

  __attribute__((noinline)) void close_pair_acts(SurfacesCloseData &scdata, const lubricated::NormalModel &model,
                                                 ForceData &i_forces, ForceData &j_forces);

  // idle_reach(): beyond radsum + the film's reach + what both atoms can move in the step, no
  // type pair's model acts (NormalModel::acts false: gap >= reach(R) + |u_n| dt). The reach is
  // 0.75 dx with a grid, else eps_al R with R = 2 r_i r_j / (r_i + r_j) <= radsum / 2; each atom's
  // move is bounded by the largest |v|_1 dt of the rank's atoms, ghosts included (v^(n-1/2), as
  // u_n). A relative margin of 1e-9 covers the rounding of the tests. A continued run's kick
  // changes u_n: no pair is idle there.
  void bound_idle_pairs();

  // lambda(eps_al) of a contact's film (Lubrication::lambda_activation_for, a logarithm): kept in
  // the contact's history with eps_al as its key, which fixes it (the film radius and the grid
  // spacing and saturation enter through eps_al alone, within rounding); a new contact's history
  // is zero, no eps_al. A sustained contact so takes one logarithm, not one per step.
  __attribute__((always_inline)) double history_lambda(const lubricated::Lubrication &film,
                                                       const lubricated::FilmRadius &radius, double *history)
  {
    if (lambda_offset_ < 0 || !history || film.grid_spacing <= 0.0) return film.lambda_activation_for(radius);
    double *kept = history + lambda_offset_;
    const double eps_al = film.activation_for(radius);
    if (kept[0] != eps_al) kept[0] = eps_al, kept[1] = film.lambda_activation_for(radius);
    return kept[1];
  }

  // LAMMPS's group `all` (always the first group).
  static constexpr int all_group_bit = 1;

  // Whether this pass (of the pair) leaves the close pairs of one wet type pair with the exact
  // contact to one loop at its end (close_pairs.h): a step, plain reduced masses, forces applied, and
  // nothing that reads each pair's force (virial, compute pair/gran/local, stored contact
  // forces, summed normal forces).
  bool defer_close_pairs(const SurfacesIntersectData &sidata);

  // The type pair whose close pairs the loop takes this pass: the first wet one with the exact
  // contact (the others one by one).
  bool first_close_type(int t)
  {
    if (close_type_ >= 0 || !(models_[t].exact && models_[t].lubrication.active())) return false;
    close_type_ = t;
    return true;
  }

  // The film's radius: 2 r_i r_j / (r_i + r_j) for a pair, r_i at a wall (lubrication.h).
  lubricated::FilmRadius film_radius(const SurfacesCloseData &scdata) const
  {
    return is_wall_ ? lubricated::FilmRadius(scdata.radi) : lubricated::film_radius_pair(scdata.radi, scdata.radj);
  }

  // The mass a contact moves, in overlap and near it (LIGGGHTS gives sidata.meff in overlap only):
  // a rigid body's mass for its atoms, the partner's mass alone against an atom no contact moves
  // (immovable()). A wall's meff is set before either call.
  double reduced_mass(const SurfacesCloseData &scdata) const
  {
    if (is_wall_) return static_cast<const SurfacesIntersectData &>(scdata).meff;
    return pair_reduced_mass(scdata.i, scdata.j);
  }

  __attribute__((always_inline)) double pair_reduced_mass(int i, int j) const
  {
    const double *rmass = atom->rmass;
    if (plain_masses_) return lubricated::reduced_mass(rmass[i], rmass[j]);
    return held_pair_reduced_mass(i, j);
  }

  // pair_reduced_mass where some atoms are held or in rigid bodies.
  double held_pair_reduced_mass(int i, int j) const
  {
    double m_i, m_j;
    atom_masses(i, j, m_i, m_j);
    const bool held_i = immovable(i), held_j = immovable(j);
    if (held_j && !held_i) return m_i;
    if (held_i && !held_j) return m_j;
    const int frozen = pair_->freeze_group_bit(), *mask = atom->mask;    // LIGGGHTS's own
    if (mask[j] & frozen) return m_i;
    if (mask[i] & frozen) return m_j;
    return lubricated::reduced_mass(m_i, m_j);
  }

  // The spheres' masses, a rigid body's for its atoms (as LIGGGHTS's sidata.meff).
  void atom_masses(int i, int j, double &m_i, double &m_j) const
  {
    m_i = atom->rmass[i];
    m_j = atom->rmass[j];
    if (pair_->fr_pair()) {
      const double *body_mass = pair_->mr_pair();
      if (body_mass[i] > 0.0) m_i = body_mass[i];
      if (body_mass[j] > 0.0) m_j = body_mass[j];
    }
  }

  // The masses of a pair's atoms as the contact moves them: infinite for an atom no contact
  // moves (the network check's sums; contact_network.h).
  void contact_masses(const SurfacesCloseData &scdata, double &m_i, double &m_j) const
  {
    atom_masses(scdata.i, scdata.j, m_i, m_j);
    if (immovable(scdata.i)) m_i = INFINITY;
    if (immovable(scdata.j)) m_j = INFINITY;
  }

  // Atoms no contact moves: left out of every time integration, or in the group of fix freeze,
  // fix move or fix setforce 0 0 0 without a region (the LAMMPS plugin's contact masses).
  void find_immovable_groups();

  bool immovable(int i) const
  {
    const int mask = atom->mask[i];
    return (mask & hold_bits_) || !(mask & integrate_bits_);
  }

  // The checks and the description every adapter gives (lubricated/check_setup.h): one line
  // per type pair of this pair style (or per atom type at this wall), each WARNING once.
  void report_setup(const char *caller);

  // A sphere of radius r, smaller than the smallest at the run's start (r_start), appeared: the
  // film of a grid spacing reaches 0.75 dx whatever the radius, i.e. farther in units of its
  // radius. Checked (eps_al <= 1) and covered as at the run's start, before the neighbor build.
  void smaller_radius(double r, double r_start, const char *caller);

  // LIGGGHTS 3.8.0 lists a sphere near a primitive wall when its gap is below the neighbor skin at
  // a build (FixWallGran::pre_force: PrimitiveWall::buildNeighList(skin)), whatever the contact
  // distance factor, and rebuilds once a sphere moved skin / 2: a sphere left out can close to a
  // gap of skin / 2 unseen. Its film, reaching 0.75 dx (or eps_al r), is then missed for part of
  // the approach (e 0.4444 instead of 0.4333 at skin 5e-5, 0.75 dx = 1.5e-4). A mesh wall's list
  // (FixNeighlistMesh) covers r * factor + skin / 2 and needs no check.
  void check_primitive_wall_list(const char *caller);

  // The pair's model creates the budget fix (and keeps it after the walls); a wall joins it when
  // it exists. Dry scenes take no part: the fix then does nothing.
  void join_film_budget(const char *caller);

  // At each neighbor list build (and a new time step): the share bounds of the pairs of the list
  // that can reach the film before the next build (they close by at most the skin), summed per
  // atom with the walls' by the budget fix, which skips the budget where no sum exceeds 1.
  void bound_film_shares();

  // Loads of a sustained contact per type pair (contact_network.h): the exact normal contact's,
  // and the larger of it and LIGGGHTS's explicit tangential spring-dashpot's (kt = 2/7 k and
  // gammat = 2/7 c on the tangential mass 2/7 m_e: the sampled normal load). True when one
  // can matter.
  bool network_loads(std::vector<double> &normal, std::vector<double> &bound) const;

  // The film's share of its cap over the time it acts before the next evaluation (film_budget.h).
  void record_film(const SurfacesCloseData &scdata, double film, const double *en, double m_e, double u_n,
                   bool continued)
  {
    const double kick = evaluation_kind(continued).kick_time;
    const double f[3] = {film * en[0], film * en[1], film * en[2]};
    budget_->add_film(scdata.i, is_wall_ ? -1 : scdata.j, f, lubricated::film_share(film, m_e, u_n, kick));
  }

  // LIGGGHTS integrates with velocity Verlet (fix nve/sphere); a set-up that continues the last
  // run evaluates as its step did (fix_lubricated_step_velocity.h).
  bool stepping(bool continued) const { return !update->setupflag || continued; }
  lubricated::EvaluationKind evaluation_kind(bool continued) const
  {
    return lubricated::evaluation_kind(update->dt, update->setupflag != 0, continued, false);
  }
  lubricated::Evaluation evaluation(bool continued) const { return evaluation_kind(continued).when; }

  // The partner atom of a pair, -1 at a wall.
  int partner(const SurfacesCloseData &scdata) const { return is_wall_ ? -1 : scdata.j; }

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
  void build_models();

  // A contact whose previous step was not evaluated: its entry is integrated approximately.
  void missed_approach(double u_n);

  // The overlap check (lubricated/overlap_check.h), as in the LAMMPS plugin: a contact of type
  // pair t overlapping by more than overlap_depth_ of the smaller radius (a wall: the sphere's)
  // warns, once per run beyond each of the two limits (overlap_depth_ then rises to the next;
  // reset at each run's init). Pairs of two immovable atoms are not checked.
  double smaller_radius(const SurfacesIntersectData &sidata) const
  {
    return is_wall_ ? sidata.radi : std::min(sidata.radi, sidata.radj);
  }
  __attribute__((noinline)) void check_overlap(const SurfacesIntersectData &sidata, double gap, int t);
  double overlap_depth_ = lubricated::overlap_warning_fraction;
  bool overlap_warned_ = false, overlap_deep_warned_ = false;

  bool is_wall_;
  LAMMPS_NS::PairGran *pair_;
  IContactHistorySetup *hsetup_;              // the pair style or the wall fix
  double bound_dt_ = -1.0;                    // the time step of the last share bounds
  int integrate_bits_ = 0, hold_bits_ = 0;    // group bits: integrated, held (immovable())
  lubricated::liggghts::FixLubricatedFilmBudget *budget_ = nullptr;
  lubricated::liggghts::FixLubricatedStepVelocity *step_velocity_ = nullptr;
  bool budget_on_ = false;
  bool defer_close_ = false;    // this pass lists its close pairs for ClosePairs::apply (apply_close_pairs)
  int close_type_ = -1;         // their type pair
  lubricated::liggghts::ClosePairs close_;
  bool plain_masses_ = false;    // this pass: every atom integrated, none held or rigid (beginPass)
  bool warned_ = false;
  std::string message_;
  int ntypes_ = 0;
  double dt_ = -1.0;
  int lambda_offset_ = -1;                              // eps_al, lambda(eps_al) in a pair's contact history (-1: none)
  double idle_scale_ = 1.0, idle_offset_ = INFINITY;    // idle_reach() (pairs; walls: none idle)
  double film_eps_max_ = 0.0, film_reach_max_ = 0.0;    // the films' largest eps_al, grid reach
  std::vector<lubricated::Coefficients> coefficients_;
  std::vector<lubricated::NormalModel> models_;
};

}    // namespace ContactModels
}    // namespace LIGGGHTS

#endif
