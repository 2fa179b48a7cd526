/* ----------------------------------------------------------------------
   fix wall/lubrication/region (see doc/fix_wall_lubrication_region.rst)

   fix ID group wall/lubrication/region e_d regionID [keyword value ...]
     keywords as in pair_coeff of pair_style lubricated/springdashpot
     and cavitation dp_c|none: the separating film's tension limit, as in fix wall/lubrication
------------------------------------------------------------------------- */

#include "fix_wall_lubrication_region.h"

#include "unit_style/unit_style.h"

#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "lubricated/film_budget.h"
#include "lubricated/wall_curvature.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "region.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix wall/lubrication/region";

namespace {
// The rotation's point and unit axis are protected members of Region; a pointer to a member,
// taken in a derived class, reads them without copying LAMMPS's code (never instantiated).
struct RegionAxis : Region {
  static const double *point_of(const Region *r) { return r->*(&RegionAxis::point); }
  static const double *axis_of(const Region *r) { return r->*(&RegionAxis::runit); }
};
}    // namespace

FixWallLubricationRegion::FixWallLubricationRegion(LAMMPS *lmp, int narg, char **arg) :
    FixWallLubricationBase(lmp, narg, arg)
{
  ContactMass::watch_setforce(lmp);
  require_supported_units(lmp, STYLE);
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "{} requires atom_style sphere (per-atom radius and rmass)", STYLE);
  if (narg < 5) error->all(FLERR, "{}: expected e_d and a region ID (fix ID group {} e_d regionID ...)", STYLE, style);

  // e_d, then the coefficient keywords after the region ID, exactly as in pair_coeff; among
  // them cavitation, as after the walls of fix wall/lubrication.
  std::vector<std::string> words{arg[3]};
  bool seen_cavitation = false;
  for (int iarg = 5; iarg < narg; iarg++) {
    if (strcmp(arg[iarg], "cavitation") != 0) {
      words.emplace_back(arg[iarg]);
      continue;
    }
    if (iarg + 1 >= narg) error->all(FLERR, "{}: cavitation needs 1 value", STYLE);
    parse_cavitation(STYLE, arg[++iarg], seen_cavitation);
  }
  const std::string problem = lub::parse_coefficients(words, 0, coeffs);
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);

  region_id = arg[4];
  region = domain->get_region_by_id(region_id);
  if (!region) error->all(FLERR, "{}: region {} does not exist", STYLE, region_id);
  if (region->varshape)
    error->all(FLERR,
               "{}: region {} changes its shape with variables (not supported: the wall's velocity "
               "would miss the shape change; use the region's move or rotate keywords)",
               STYLE, region_id);
  slots = region->tmax;

  scalar_flag = 1;    // elastic energy stored in the wall springs
  vector_flag = 1;    // force and torque of the wall on the group
  size_vector = 6;
  global_freq = 1;
  extscalar = 1;
  extvector = 1;
  energy_global_flag = 1;
  dynamic_group_allow = 1;
  restart_global = 1;    // the region's last displacement (its velocity at a continued set-up)

  if (coeffs.tangential() && !(atom->omega_flag && atom->torque_flag))
    error->all(FLERR, "{} with friction, rolling or shearfilm requires per-atom omega and torque (atom_style sphere)",
               STYLE);
  if (keeps_history()) {
    restart_peratom = 1;
    create_attribute = 1;
    maxexchange = slots * SLOT;
    grow_arrays(atom->nmax);
    for (int i = 0; i < atom->nmax; i++)
      set_arrays(i);
    atom->add_callback(Atom::GROW);
    atom->add_callback(Atom::RESTART);
  }
}

FixWallLubricationRegion::~FixWallLubricationRegion()
{
  if (keeps_history()) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  memory->destroy(history);
}

void FixWallLubricationRegion::init()
{
  region = domain->get_region_by_id(region_id);
  if (!region) error->all(FLERR, "{}: region {} does not exist", STYLE, region_id);
  if (region->tmax != slots)
    error->all(FLERR, "{}: region {} was redefined with another number of faces", STYLE, region_id);
  // LAMMPS reports one curvature radius per contact (Region::Contact::radius, 0 for a flat
  // face): +-R_s for a sphere (+ outside, - inside: this project's sign) and +-2 R_c on a
  // cylinder's curved face; other styles are read as flat (doc: "Curved surfaces").
  const std::string kind = region->style;
  shape = kind == "sphere" ? Shape::sphere : kind == "cylinder" ? Shape::cylinder : Shape::flat;

  init_model(STYLE, "region " + region_id + " (" + kind + "), ");
  const std::string problem = lub::validate_grid_for_radius(coeffs, smallest_sphere_radius(lmp, STYLE, groupbit));
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);
}

void FixWallLubricationRegion::reset_dt()
{
  model = lub::make_contact_model(coeffs, lub::Partner::wall, update->dt, &model);
}

// The region's displacement and angle at this step (Region::prematch evaluates its variables),
// differenced with the last step's: V and Omega over the last step, as the atoms' velocities
// are. The first evaluation has no last step: the region is taken at rest there. A second
// evaluation at the same step (a set-up that continues the run, `run 0`) keeps them.
void FixWallLubricationRegion::update_motion()
{
  region->prematch();
  if (!region->dynamic) {
    motion = lub::RigidWallMotion();
    return;
  }
  const double now[4] = {region->dx, region->dy, region->dz, region->theta};
  if (update->ntimestep == last_step) return;
  const bool known = last_step >= 0 && update->ntimestep == last_step + 1;
  const double rate = known ? 1.0 / update->dt : 0.0;
  motion = lub::RigidWallMotion();
  if (region->moveflag)
    motion.velocity = {(now[0] - last_displacement[0]) * rate, (now[1] - last_displacement[1]) * rate,
                       (now[2] - last_displacement[2]) * rate};
  if (region->rotateflag) {
    const double *p = RegionAxis::point_of(region), *axis = RegionAxis::axis_of(region);
    const double angular = (now[3] - last_displacement[3]) * rate;
    motion.spin = {angular * axis[0], angular * axis[1], angular * axis[2]};
    motion.point = {p[0] + now[0], p[1] + now[1], p[2] + now[2]};
  }
  for (int k = 0; k < 4; k++)
    last_displacement[k] = now[k];
  last_step = update->ntimestep;
}

// R_f of the sphere against the face of a contact (wall_curvature.h), from LAMMPS's radius.
lub::FilmRadius FixWallLubricationRegion::film_radius(double r, double contact_radius) const
{
  if (contact_radius == 0.0 || shape == Shape::flat) return lub::FilmRadius(r);
  const double wall_radius = shape == Shape::cylinder ? 0.5 * contact_radius : contact_radius;
  const double second = shape == Shape::sphere ? wall_radius : 0.0;
  using lub::detail::number;
  if (!lub::sphere_fits_wall(r, wall_radius))
    error->one(FLERR, "{}: a sphere of radius {} does not fit inside the concave surface of radius {} of region {}",
               STYLE, number(r), number(-wall_radius), region_id);
  const double rf = lub::wall_film_radius(r, wall_radius, second);
  if (model.normal.lubrication.active() && !(rf <= MAX_FILM_RATIO * r))
    error->one(FLERR,
               "{}: a sphere of radius {} nearly fills the concave surface of radius {} of region {}: film "
               "radius R_f = {} (allowed: R_f <= {} R)",
               STYLE, number(r), number(-wall_radius), region_id, number(rf), number(MAX_FILM_RATIO));
  return lub::FilmRadius(rf);
}

void FixWallLubricationRegion::add_to_sums(const double *x, const lub::Vec3 &force, const lub::Vec3 &torque)
{
  // Torque about the reference point: the rotation point of a rotating region, else the origin.
  const lub::Vec3 arm = lub::minus({x[0], x[1], x[2]}, motion.point);
  const lub::Vec3 moment = lub::plus(lub::cross(arm, force), torque);
  local_sums[1] += force.x, local_sums[2] += force.y, local_sums[3] += force.z;
  local_sums[4] += moment.x, local_sums[5] += moment.y, local_sums[6] += moment.z;
}

void FixWallLubricationRegion::find_contacts()
{
  update_motion();
  for (int i = 0; i < atom->nlocal; i++)
    visit_atom(i, [this](int j, double mass) { contacts_of_atom(j, mass); });
}

// Every contact of atom i (contact mass `mass`) with the region's surface.
void FixWallLubricationRegion::contacts_of_atom(int i, double mass)
{
  const double *xi = atom->x[i];
  const double *vi = midpoint && model.normal.exact ? midpoint->step_velocity(i) : pass.v[i];
  // A centre outside the region is left alone (as fix wall/gran/region); one that was inside a
  // step ago went through the wall (the overlap check).
  if (!region->match(xi[0], xi[1], xi[2])) {
    if (history) release_other_slots(i, nullptr, 0);
    const double dt = update->dt;
    if (!update->setupflag && region->match(xi[0] - vi[0] * dt, xi[1] - vi[1] * dt, xi[2] - vi[2] * dt))
      check_overlap(i, -atom->radius[i], true);    // d >= R
    return;
  }
  const int nc = faces_near(i, vi);
  share_face_loads(i, nc);
  for (int ic = 0; ic < nc; ic++)
    face_contact(i, mass, ic, vi);
}

// Gravity's load on each face within reach of atom i (face_load), shared among the faces it
// overlaps (share_gravity_loads: a groove, a corner).
void FixWallLubricationRegion::share_face_loads(int i, int nc)
{
  face_load.resize(nc);
  if (gravity.empty()) {
    std::fill(face_load.begin(), face_load.end(), 0.0);
    return;
  }
  face_normal.resize(nc), face_gap.resize(nc);
  const double r = atom->radius[i];
  for (int ic = 0; ic < nc; ic++) {
    const Region::Contact &c = region->contact[ic];
    face_normal[ic] = c.r > 0.0 ? lub::Vec3{c.delx / c.r, c.dely / c.r, c.delz / c.r} : lub::Vec3{};
    face_gap[ic] = c.r - r;
    face_load[ic] = gravity_load(i, face_normal[ic]);
  }
  if (nc > 1) share_gravity_loads(i, face_normal.data(), face_gap.data(), face_load.data(), nc);
}

// The faces within reach of atom i (region->contact), whose step velocity is vi: the film's
// reach for the largest film radius allowed, and what the relative motion can close in a step
// (normal_model.h acts()). Faces no longer near the atom forget their elongation.
int FixWallLubricationRegion::faces_near(int i, const double *vi)
{
  const double *xi = atom->x[i];
  const double r = atom->radius[i];
  const lub::Vec3 arm = lub::minus({xi[0], xi[1], xi[2]}, motion.point);
  const double wall_speed = std::sqrt(lub::dot(motion.velocity, motion.velocity)) +
                            std::sqrt(lub::dot(motion.spin, motion.spin)) * (std::sqrt(lub::dot(arm, arm)) + r);
  const double speed = std::sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]) + wall_speed;
  const double cutoff =
      r + model.normal.reach(MAX_FILM_RATIO * r) + 2.0 * speed * update->dt + gravity_reach(update->dt);
  const int nc = region->surface(xi[0], xi[1], xi[2], cutoff);
  if (nc > slots)
    error->one(FLERR, "{}: {} contacts of one atom with region {} (at most {})", STYLE, nc, region_id, slots);
  if (history) {
    faces.resize(nc);
    for (int ic = 0; ic < nc; ic++)
      faces[ic] = region->contact[ic].iwall;
    release_other_slots(i, faces.data(), nc);
  }
  return nc;
}

// Atom i (contact mass `mass`, step velocity vi) at the face of region->contact[ic], applied
// where it acts.
void FixWallLubricationRegion::face_contact(int i, double mass, int ic, const double *vi)
{
  const Region::Contact &c = region->contact[ic];
  if (c.r <= 0.0) return;    // a centre on the surface has no normal
  const double *xi = atom->x[i], *v = pass.v[i], *omega = pass.omega[i];
  const double r = atom->radius[i];
  WallContact contact;
  contact.n = {c.delx / c.r, c.dely / c.r, c.delz / c.r};
  const lub::Vec3 &n = contact.n;
  contact.film = film_radius(r, c.radius);
  contact.gap = c.r - r;
  const bool moving = motion.moving();
  lub::RelativeMotion rel;
  if (moving) {
    // Relative to the wall's material point at the contact; u_n with the velocity over the
    // last step (fix nve/sphere/midpoint's where it integrates).
    const lub::Vec3 contact_point{xi[0] - c.delx, xi[1] - c.dely, xi[2] - c.delz};
    rel = lub::relative_to_wall(motion, {v[0], v[1], v[2]}, {omega[0], omega[1], omega[2]}, r, n, contact_point);
    if (midpoint && model.normal.exact)
      rel.u_n = lub::dot(lub::minus({vi[0], vi[1], vi[2]}, motion.velocity_at(contact_point)), n);
  } else {
    rel.u_n = vi[0] * n.x + vi[1] * n.y + vi[2] * n.z;
  }
  contact.u_n = rel.u_n;
  contact.load = face_load[ic];    // gravity pressing the atom onto the face (share_face_loads)
  if (!model.normal.acts(contact.gap, contact.film.value, contact.u_n, contact.load)) {
    if (history) forget_slot(i, c.iwall);
    return;
  }
  double *h = history ? history_slot(i, c.iwall) : nullptr;
  contact.history = h ? h + 1 : nullptr;    // the face id, then elongation x y z and touched
  if (model.tangential.active()) {
    contact.dv = moving ? rel.dv : lub::Vec3{v[0], v[1], v[2]};
    contact.omega = moving ? rel.omega : lub::Vec3{omega[0], omega[1], omega[2]};
    contact.reduced_radius = r;
  }
  apply_contact(i, mass, contact);
}

// Every atom of the group counts as near each face it may touch at once (tmax), with the bound
// of the largest film radius allowed.
void FixWallLubricationRegion::add_film_share_bounds(double *bound, int nlocal) const
{
  if (!model.normal.lubrication.active()) return;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const bool shear_film = model.tangential.film_active();
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      bound[i] += slots * (shear_film ? 1.0
                                      : lub::film_share_bound(model.normal.lubrication, MAX_FILM_RATIO * radius[i],
                                                              rmass[i], update->dt));
}

// A force and torque on atom i in the outputs: the force and torque on the group.
void FixWallLubricationRegion::tally(int i, const lub::Vec3 &force, const lub::Vec3 &torque)
{
  add_to_sums(atom->x[i], force, torque);
}
