/* ----------------------------------------------------------------------
   The wall fixes' evaluation (fix_wall_lubrication_base.h): its shared preamble, then the
   contacts a wall style finds, each applied here once: the kernel's forces on the atom and in
   the outputs, the films deferred to post_force, the sustained contacts and the history.
------------------------------------------------------------------------- */

#include "fix_wall_lubrication_base.h"

#include "film_budget/film_budget.h"
#include "fix_step_velocity/fix_step_velocity.h"
#include "lubricated/film_budget.h"
#include "lubricated/film_cavitation.h"
#include "lubricated/film_link.h"
#include "lubricated/load_sharing.h"
#include "lubricated/overlap_check.h"

#include "atom.h"
#include "error.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>

using namespace LAMMPS_NS;
namespace lub = lubricated;

// One evaluation: the shared preamble, then the wall style's contacts.
void FixWallLubricationBase::compute_walls(bool defer_films)
{
  begin_evaluation(defer_films);
  find_contacts();
}

// The velocities, the kind of evaluation, the outputs and the deferred films of this
// evaluation, and the contact masses where some atoms are held or in rigid bodies.
void FixWallLubricationBase::begin_evaluation(bool defer_films)
{
  // A set-up that continues the last run evaluates as its last step did, with its velocities
  // (fix_step_velocity.h); not with rigid bodies or immovable atoms.
  const bool continued = step_velocity && step_velocity->continues() && !contact_mass.holds_or_rigid();
  pass.v = continued ? step_velocity->velocity() : atom->v;
  pass.omega = continued ? step_velocity->spin() : atom->omega;
  const lub::EvaluationKind kind =
      lub::evaluation_kind(update->dt, update->setupflag != 0, continued, midpoint != nullptr);
  pass.when = kind.when;

  clear_sums();
  films_pending = pass.defer_films = defer_films && model.normal.lubrication.active();
  shear_pending = pass.defer_films && model.tangential.film_active();
  // The links of the coupled solve, where it can be taken this step.
  links_pending = pass.defer_films && pair_budget && pair_budget->solves() && pair_budget->may_be_active();
  clear_films();
  pass.kick_time = kind.kick_time;

  // m_e = m; the body's mass for an atom of a rigid body; an immovable atom is left alone.
  // Atoms change index only where the lists are rebuilt (or a run starts).
  pass.by_inverse = contact_mass.active();
  const int nlocal = atom->nlocal;
  if (pass.by_inverse && (neighbor->ago == 0 || update->setupflag || static_cast<int>(inverse_mass.size()) < nlocal)) {
    if (static_cast<int>(inverse_mass.size()) < nlocal) inverse_mass.resize(atom->nmax);
    contact_mass.fill(inverse_mass.data());
  }
}

void FixWallLubricationBase::apply_contact(int i, double mass, const WallContact &contact)
{
  if (contact.gap < -lub::overlap_warning_fraction * atom->radius[i]) check_overlap(i, contact.gap, false);
  // The fluid's added mass (contact_mass.h) moves with the atom along n, and slows its load.
  if (contact_mass.carries_added_mass()) {
    WallContact carried = contact;
    const double m_e = contact_mass.along_normal(i, contact.n.x, contact.n.y, contact.n.z, mass);
    carried.load *= contact_mass.own_fraction(i, m_e);
    apply_contact_of_mass(i, m_e, carried);
    return;
  }
  apply_contact_of_mass(i, mass, contact);
}

void FixWallLubricationBase::apply_contact_of_mass(int i, double mass, const WallContact &contact)
{
  record_sustained(i, contact.gap, contact.u_n, contact.n);
  lub::ContactForces forces = contact_forces_of(i, mass, contact);
  if (cavitation >= 0.0) relieve_cavitation(forces, contact);
  const double normal = defer_contact_films(i, mass, contact, forces);
  local_sums[0] += forces.normal.energy;
  add_contact_force(i, lub::scaled(contact.n, normal), model.tangential.active() ? &forces : nullptr);
}

lub::ContactForces FixWallLubricationBase::contact_forces_of(int i, double mass, const WallContact &contact)
{
  lub::ContactPoint p;
  p.gap = contact.gap, p.u_n = contact.u_n, p.reduced_mass = mass, p.film = contact.film;
  p.load = contact.load;
  lub::HistorySlot slot;
  double *h = contact.history;
  const bool tangential_on = model.tangential.active();
  if (tangential_on) {
    p.n = contact.n;
    p.dv = contact.dv;
    p.omega_i = contact.omega;
    p.radius_i = atom->radius[i], p.reduced_radius = contact.reduced_radius;
    p.mass_i = atom->rmass[i];    // the sphere's own inertia, also in a rigid body
    // An added mass moves with the sphere, not with its turning (contact_mass.h).
    if (contact_mass.carries_added_mass())
      p.tangential_mass = lub::tangential_mass_of_sides(1.0 / mass, atom->rmass[i], 0.0, 0.0);
    if (h) slot = lub::history_slot(h, h[3], !update->setupflag);
  }
  const lub::ContactForces forces =
      tangential_on ? lub::contact_forces<true, lub::Partner::wall>(model, p, slot, pass.when, shear_pending)
                    : lub::contact_forces<false, lub::Partner::wall>(model, p, slot, pass.when);
  if (h) h[3] = lub::history_flag(slot);
  return forces;
}

// In a wet run the films wait for post_force, within the atom's film budget: the normal film's
// force and share, with the shear film its force and torque and the contact's share the larger
// of the two films' (film_budget.h). Returns the normal force to apply now.
double FixWallLubricationBase::defer_contact_films(int i, double mass, const WallContact &contact,
                                                   const lub::ContactForces &forces)
{
  const lub::NormalForce &fn = forces.normal;
  if (!pass.defer_films) return fn.total();
  const std::size_t entry = film_entry(i);
  if (links_pending) record_film_link(i, entry, contact);
  double *ff = &film_force[3 * entry];
  const lub::Vec3 &n = contact.n;
  ff[0] += fn.lubrication * n.x, ff[1] += fn.lubrication * n.y, ff[2] += fn.lubrication * n.z;
  const double share = lub::film_share(fn.lubrication, mass, contact.u_n, pass.kick_time);
  if (!shear_pending) {
    film_load[entry] += share;
    return fn.contact;
  }
  film_load[entry] += lub::contact_film_share(share, forces.shear_share(pass.kick_time));
  double *out = &shear_film[6 * entry];
  out[0] += forces.shear.x, out[1] += forces.shear.y, out[2] += forces.shear.z;
  out[3] += forces.shear_torque_i.x, out[4] += forces.shear_torque_i.y, out[5] += forces.shear_torque_i.z;
  return fn.contact;
}

// The contact's films as a link of the coupled solve, at the velocities of this evaluation.
void FixWallLubricationBase::record_film_link(int i, std::size_t entry, const WallContact &contact)
{
  const double *v = pass.v[i];
  const bool tangential = model.tangential.active();    // else no spin is read (nor needed)
  const double *omega = tangential ? pass.omega[i] : nullptr;
  const lub::Vec3 spin = omega ? lub::Vec3{omega[0], omega[1], omega[2]} : lub::Vec3{};
  const lub::Vec3 wall_velocity =
      lub::wall_velocity_at_contact({v[0], v[1], v[2]}, spin, atom->radius[i], contact.n, contact.u_n,
                                    tangential ? &contact.dv : nullptr, tangential ? &contact.omega : nullptr);
  film_link.push_back(
      lub::wall_film_link(model, i, contact.n, contact.gap, contact.film, contact.reduced_radius, wall_velocity));
  link_entry.push_back(static_cast<int>(entry));
}

// The contact's normal force, and its tangential force and torque where the model has them, on
// atom i and in the sums.
void FixWallLubricationBase::add_contact_force(int i, const lub::Vec3 &normal, const lub::ContactForces *tangential)
{
  double *fi = atom->f[i];
  if (!tangential) {
    fi[0] += normal.x, fi[1] += normal.y, fi[2] += normal.z;
    tally(i, normal, lub::Vec3());
    return;
  }
  const lub::Vec3 &torque = tangential->torque_i;
  double *ti = atom->torque[i];
  ti[0] += torque.x, ti[1] += torque.y, ti[2] += torque.z;
  if (adds_tangential_apart) {
    const lub::Vec3 &force = tangential->tangential;
    fi[0] += normal.x, fi[1] += normal.y, fi[2] += normal.z;
    tally(i, normal, lub::Vec3());
    fi[0] += force.x, fi[1] += force.y, fi[2] += force.z;
    tally(i, force, torque);
    return;
  }
  const lub::Vec3 force = lub::plus(normal, tangential->tangential);
  fi[0] += force.x, fi[1] += force.y, fi[2] += force.z;
  tally(i, force, torque);
}

// A separating film holds no more tension than the liquid can before it cavitates: the part of
// the film force beyond it is removed (film_cavitation.h); the film's gap is held at eps_1 R below.
void FixWallLubricationBase::relieve_cavitation(lub::ContactForces &forces, const WallContact &contact) const
{
  const lub::Lubrication &film_law = model.normal.lubrication;
  const double radius = contact.film.value;
  const double gap = std::max(contact.gap, film_law.eps_saturation * radius);
  forces.normal.lubrication +=
      lub::cavitation_relief(film_law.six_pi_mu, radius, gap, contact.u_n, cavitation, forces.normal.lubrication);
}

// Where the overlap passes a limit (apply_contact), or the centre went behind the wall. A centre
// behind the wall it touched is an ERROR on this rank (the atom would be lost); an overlap beyond
// either limit a WARNING, once per run for each (a deep but held contact, as in dense 1:10 beds
// pressed onto a wall, stays stable).
__attribute__((noinline)) void FixWallLubricationBase::check_overlap(int i, double gap, bool through)
{
  const double r = atom->radius[i];
  const double fraction = lub::overlap_fraction(gap, r);
  const lub::OverlapLevel level = through ? lub::OverlapLevel::error : lub::overlap_level(fraction);
  if (level == lub::OverlapLevel::none) return;
  const bool deep = level == lub::OverlapLevel::error;
  if (!through && (deep ? overlap_deep_warned : overlap_warned)) return;
  const std::string who =
      fmt::format("atom {} (type {}) and the wall of fix {} ({})", atom->tag[i], atom->type[i], id, style);
  const std::string text = lub::overlap_message(who, gap, r, fraction, coeffs, update->dt, through, true);
  if (through) error->one(FLERR, "{}", text);
  overlap_warned = true;
  overlap_deep_warned = deep;
  error->warning(FLERR, "{}", text);
}

void FixWallLubricationBase::share_gravity_loads(int i, const lub::Vec3 *normal, const double *gap, double *load,
                                                 int count) const
{
  lub::Vec3 touching[lub::max_shared_loads];
  int index[lub::max_shared_loads], m = 0;
  for (int k = 0; k < count; k++)
    if (gap[k] < 0.0 && load[k] > 0.0) {
      if (m == lub::max_shared_loads) return;    // more faces than a sphere can rest on: as they are
      index[m] = k, touching[m++] = normal[k];
    }
  if (m < 2) return;
  lub::Vec3 g;
  for (const Gravity &each : gravity)
    if (atom->mask[i] & each.groupbit)
      g = lub::plus(g, {each.acceleration[0], each.acceleration[1], each.acceleration[2]});
  double shared[lub::max_shared_loads];
  lub::shared_loads(touching, m, g, shared);
  for (int k = 0; k < m; k++)
    load[index[k]] = shared[k];
}
