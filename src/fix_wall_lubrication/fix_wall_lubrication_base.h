/* -*- c++ -*- ----------------------------------------------------------
   What the two wall fixes of the plugin share (fix wall/lubrication, fix
   wall/lubrication/region): the coefficients and the contact model, the run's order of work,
   the check and description at init, the application of one contact, and the wall films' part
   in the many-body film budget. A wet wall is computed before the pair style (pre_force) and
   its films applied after it (post_force), scaled by the atoms' budget; a dry wall is computed
   after the pair style. Each wall style only finds its contacts (find_contacts: the geometry,
   the wall's velocity and curvature) and hands each to apply_contact; it also bounds its
   walls' film shares.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_WALL_LUBRICATION_BASE_H
#define LMP_FIX_WALL_LUBRICATION_BASE_H

#include "atom.h"
#include "fix.h"
#include "update.h"

#include "contact_mass/contact_mass.h"
#include "contact_network/contact_network_participant.h"
#include "film_budget/film_budget_participant.h"
#include "lubricated/contact.h"

#include <cmath>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixWallLubricationBase : public Fix, public FilmBudgetParticipant, public ContactNetworkParticipant {
 public:
  FixWallLubricationBase(class LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg), contact_mass(lmp) {}

  void post_constructor() override;
  int setmask() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void min_setup(int) override;
  void pre_force(int) override;
  void post_force(int) override;
  void min_post_force(int) override;
  // The outputs: the walls' spring energy (scalar) and the size_vector sums the fix defines
  // (force of the walls on the group, and the region's torque), summed over the ranks once.
  double compute_scalar() override;
  double compute_vector(int) override;
  // The deferred films, their links and the contact masses; walls add their histories.
  double memory_usage() override;

  bool wet() const override { return coeffs.wet(); }
  // Adds this step's wall-film shares to the owned atoms' loads of the many-body film budget
  // (film_budget/film_budget.h, which sums them with the pair style's).
  void add_film_loads(double *load, int nlocal) const override;
  // Adds to each owned atom the bound on its wet walls' film shares (lubricated/film_budget.h).
  void add_film_share_bounds(double *bound, int nlocal) const override = 0;
  // The pair style's coupled film solve (`limit implicit`): the deferred films of atoms over
  // budget as links, then their solved forces in place of the step-exact ones (apply_films).
  int add_film_links(const double *scale, std::vector<lubricated::FilmLink> &links) override;
  void take_solved_films(const lubricated::FilmLinkForce *solved, int count) override;

  // The contacts of the last evaluation in overlap then and a step before (sustained), for the
  // pair style's contact-network check (contact_network/contact_network_check.h).
  const std::vector<SustainedContact> &sustained_contacts() const override { return sustained; }
  const lubricated::ContactModel &contact_model() const override { return model; }
  const lubricated::Coefficients &coefficients() const override { return coeffs; }

 protected:
  lubricated::Coefficients coeffs;
  lubricated::ContactModel model;                    // derived from coeffs and dt
  class FixNVESphereMidpoint *midpoint = nullptr;    // the paper's integrator, if in use
  class FixStepVelocity *step_velocity = nullptr;    // the last step's velocities for a set-up
  const class FilmBudget *pair_budget = nullptr;     // the lubricated pair style's, if there is one

  // One contact of an atom with a wall, as a wall style finds it.
  struct WallContact {
    double gap = 0.0, u_n = 0.0;    // the gap and the normal velocity over the last step
    double load = 0.0;              // gravity along n, pressing the atom onto the wall where > 0
    lubricated::Vec3 n;             // unit normal from the wall to the atom
    lubricated::FilmRadius film;    // the normal film's radius R_f
    // Read only where the model has tangential parts: the sphere's velocity and spin relative
    // to the wall at the contact, and the radius of the shear film and of rolling.
    lubricated::Vec3 dv, omega;
    double reduced_radius = 0.0;
    double *history = nullptr;    // friction history: elongation x y z, then the touched flag
  };
  // This evaluation (begin_evaluation): the velocities it reads (the last step's for a set-up
  // that continues a run), its kind, whether its films wait for post_force and their kick time,
  // and whether contact masses come from inverse_mass.
  struct Pass {
    double **v = nullptr, **omega = nullptr;
    lubricated::Evaluation when = lubricated::Evaluation::step;
    bool defer_films = false;
    double kick_time = 0.0;
    bool by_inverse = false;
  } pass;
  // The wall style's contacts of this evaluation, each handed to apply_contact.
  virtual void find_contacts() = 0;
  // Calls visit(i, m_e) for owned atom i of the group unless it is immovable: m_e = m, the
  // body's mass for an atom of a rigid body.
  template <class Visit> [[gnu::always_inline]] inline void visit_atom(int i, Visit &&visit)
  {
    if (!(atom->mask[i] & groupbit)) return;
    if (!pass.by_inverse)
      visit(i, atom->rmass[i]);
    else if (inverse_mass[i] > 0.0)
      visit(i, 1.0 / inverse_mass[i]);
  }
  // The contact of owned atom i (contact mass m_e = mass) on the atom and in the outputs: force,
  // torque, energy, the deferred films, the sustained contacts and the friction history.
  void apply_contact(int i, double mass, const WallContact &contact);
  void apply_contact_of_mass(int i, double mass, const WallContact &contact);
  // The tension limit dp_c of a separating film (lubricated/film_cavitation.h; < 0: none, the
  // film as printed); the walls' keyword cavitation sets it (parse_cavitation: the value word,
  // `seen` refusing a second one).
  double cavitation = -1.0;
  void parse_cavitation(const char *style, const char *value, bool &seen);
  void relieve_cavitation(lubricated::ContactForces &forces, const WallContact &contact) const;
  // A force and torque on atom i in the fix's vector sums (the energy is sums[0]).
  virtual void tally(int i, const lubricated::Vec3 &force, const lubricated::Vec3 &torque) = 0;
  // How a contact's tangential force joins its normal force: the plane and cylinder walls add
  // them to the atom and the sums one after the other, the region wall their sum (its torque
  // about the reference point is taken of the sum). The two orders round differently; each
  // wall keeps its own, so that its results stay the same to the last bit.
  bool adds_tangential_apart = false;

  // Deferred films (a run): per owned atom with a film (film_atom, in the order the walls meet
  // them, each atom's walls together) the normal films' force x y z and their summed share, and
  // with the shear film its force x y z and torque x y z, scaled with the normal films (one
  // contact's share: the larger of the two films'); valid while films_pending.
  std::vector<int> film_atom;
  std::vector<double> film_force, film_load, shear_film;
  void clear_films();
  std::size_t film_entry(int i);
  bool films_pending = false, shear_pending = false;
  // Under the pair style's `limit implicit` (links_pending): each deferred contact's films as a
  // link of the coupled solve (lubricated/film_link.h) and its entry; those the solve took
  // (solved_link), and the entries whose films it replaced (entry_solved: applied unscaled).
  bool links_pending = false;
  std::vector<lubricated::FilmLink> film_link;
  std::vector<int> link_entry, solved_link;
  std::vector<char> entry_solved;
  void record_film_link(int i, std::size_t entry, const WallContact &contact);
  // Immovable atoms (skipped: the wall cannot move them) and rigid bodies (m_e = M_body).
  ContactMass contact_mass;
  std::vector<double> inverse_mass;
  std::vector<SustainedContact> sustained;
  void record_sustained(int i, double gap, double u_n, const lubricated::Vec3 &n)
  {
    if (gap < 0.0 && gap - u_n * update->dt < 0.0) sustained.push_back({atom->tag[i], {n.x, n.y, n.z}});
  }
  // energy, then the vector's sums (at most 6), this rank's and all ranks'
  static constexpr int MAX_SUMS = 7;
  double local_sums[MAX_SUMS] = {}, global_sums[MAX_SUMS] = {};
  bool sums_reduced = false;
  void clear_sums();

  // At init: t_c settled, the set-up checked and described (`what` names the walls), the
  // integrator, the step-velocity fix, the pair style and the contact masses found.
  void init_model(const char *style, const std::string &what);
  // fix gravity of this run (init_model): its acceleration vector (read at each step: a variable
  // gravity updates it) and group. The steps where a wall contact starts or ends follow the
  // trajectory under it (lubricated/loaded_contact.h, doc/model.rst "Contacts under a steady load").
  struct Gravity {
    const double *acceleration;
    int groupbit;
  };
  std::vector<Gravity> gravity;
  void find_gravity();
  // Gravity on atom i along n (from the wall to the atom), as the contact's load: > 0 pressing
  // the atom onto the wall.
  double gravity_load(int i, const lubricated::Vec3 &n) const
  {
    double load = 0.0;
    for (const Gravity &g : gravity)
      if (atom->mask[i] & g.groupbit)
        load -= g.acceleration[0] * n.x + g.acceleration[1] * n.y + g.acceleration[2] * n.z;
    return load;
  }
  // The most gravity can move an atom towards a wall over a step, beyond |u_n| dt.
  double gravity_reach(double dt) const
  {
    double sum = 0.0;
    for (const Gravity &g : gravity)
      sum += std::sqrt(g.acceleration[0] * g.acceleration[0] + g.acceleration[1] * g.acceleration[1] +
                       g.acceleration[2] * g.acceleration[2]);
    return sum * dt * dt;
  }
  // Steady loads shared among the faces an atom overlaps (lubricated/load_sharing.h): where two
  // or three of its `count` contacts (unit normals, gaps) overlap and gravity presses the atom
  // onto them, their loads become the non-negative least-squares solution of
  // sum b_k n_k = -g; otherwise each keeps its own -g . n_k.
  void share_gravity_loads(int i, const lubricated::Vec3 *normal, const double *gap, double *load, int count) const;
  // The overlap check (lubricated/overlap_check.h): a centre gone behind the wall after a
  // contact (through) stops the run; an overlap beyond overlap_warning_fraction, and beyond
  // overlap_error_fraction, of the sphere's radius warns once per run each (reset at init).
  bool overlap_warned = false, overlap_deep_warned = false;
  void check_overlap(int i, double gap, bool through);
  // One evaluation of the walls: its films deferred to post_force where asked (a wet run).
  void compute_walls(bool defer_films);
  void begin_evaluation(bool defer_films);
  // The parts of apply_contact: the kernel's forces (and the history's touched flag), the films
  // set aside for post_force (returns the normal force applied now), the forces applied.
  lubricated::ContactForces contact_forces_of(int i, double mass, const WallContact &contact);
  double defer_contact_films(int i, double mass, const WallContact &contact, const lubricated::ContactForces &forces);
  void add_contact_force(int i, const lubricated::Vec3 &normal, const lubricated::ContactForces *tangential);
  // The deferred films, scaled by the atoms' film budget: the pair style's where it keeps one
  // (its loads include these walls), this fix's own without a lubricated pair style, none
  // under `limit pair`; tally() adds each atom's scaled film force and moment to the outputs.
  void apply_films();
};

}    // namespace LAMMPS_NS

#endif
