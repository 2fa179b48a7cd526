/* ----------------------------------------------------------------------
   The mass a contact moves (see contact_mass.h)
------------------------------------------------------------------------- */

#include "contact_mass.h"

#include "fix_fluid_drag/fix_fluid_drag.h"
#include "lubricated/drag.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <dlfcn.h>
#include <iterator>
#include <map>

using namespace LAMMPS_NS;

namespace {

// The setforce fixes created through the recording factory: whether each holds its atoms.
struct SetforceRecord {
  const LAMMPS *lmp;
  std::string id;
  bool holds;
};
std::map<const Fix *, SetforceRecord> setforce_records;
Modify::FixCreator builtin_setforce = nullptr;

bool zero_constant(const char *word)
{
  char *end = nullptr;
  const double value = strtod(word, &end);
  return end != word && *end == '\0' && value == 0.0;
}

// The built-in factory, noting `fix ID group setforce fx fy fz [region R]`: holds with three
// constant zeros and nothing after them.
Fix *create_recorded_setforce(LAMMPS *lmp, int narg, char **arg)
{
  Fix *fix = builtin_setforce(lmp, narg, arg);
  setforce_records[fix] = {lmp, fix->id,
                           narg == 6 && zero_constant(arg[3]) && zero_constant(arg[4]) && zero_constant(arg[5])};
  return fix;
}

// 1 holds, 0 does not, -1 created before the plugin was loaded (arguments unknown).
int setforce_holds(const LAMMPS *lmp, const Fix *fix)
{
  const auto found = setforce_records.find(fix);
  if (found == setforce_records.end() || found->second.lmp != lmp || found->second.id != fix->id) return -1;
  return found->second.holds ? 1 : 0;
}

}    // namespace

void ContactMass::watch_setforce(LAMMPS *lmp)
{
  if (!lmp->modify || !lmp->modify->fix_map) return;
  auto &factories = *lmp->modify->fix_map;
  const auto setforce = factories.find("setforce");
  if (setforce == factories.end() || setforce->second == &create_recorded_setforce) return;
  builtin_setforce = setforce->second;
  setforce->second = &create_recorded_setforce;
  // The map now points into this library: keep it mapped for the process's lifetime, so that a
  // `plugin unload` (dlclose) cannot leave `fix setforce` calling unmapped code.
  static bool pinned = false;
  Dl_info self;
  if (!pinned && dladdr(reinterpret_cast<void *>(&create_recorded_setforce), &self) && self.dli_fname)
    pinned = dlopen(self.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE) != nullptr;
  // A map without the recorder belongs to a new Modify (plugin load, or after `clear`): the
  // records of this instance's earlier fixes are void.
  for (auto r = setforce_records.begin(); r != setforce_records.end();)
    r = r->second.lmp == lmp ? setforce_records.erase(r) : std::next(r);
}

void ContactMass::init(const std::string &who, bool log)
{
  held_bits = integrated_bits = 0;
  any_integrator = false;
  rigid.clear();
  carried.clear();
  any_near_walls = false;
  std::vector<std::string> unknown;
  for (Fix *fix : modify->get_fix_list()) {
    const std::string style = fix->style;
    if (utils::strmatch(style, "^freeze") || utils::strmatch(style, "^move$") ||
        utils::strmatch(style, "^nve/noforce$"))
      held_bits |= fix->groupbit;
    else if (utils::strmatch(style, "^setforce$")) {
      const int holds = setforce_holds(lmp, fix);
      if (holds > 0) held_bits |= fix->groupbit;
      if (holds < 0) unknown.emplace_back(fix->id);
    }
    if (fix->time_integrate) {
      any_integrator = true;
      integrated_bits |= fix->groupbit;
    }
    if (fix->rigid_flag) rigid.push_back(fix);
    // The fluid's added mass moves with the sphere: fix fluid/drag divides the total force,
    // the contact's included, by m + m_a.
    if (const auto *drag = dynamic_cast<const FixFluidDrag *>(fix))
      if (drag->added_mass_coefficient() > 0.0) {
        carried.push_back({fix->groupbit, drag->added_mass_coefficient(), drag->fluid_density(), &drag->near_walls()});
        any_near_walls = any_near_walls || !drag->near_walls().empty();
      }
  }

  double local[3] = {0.0, 0.0, 0.0}, total[3];    // immovable, in rigid bodies, carrying added mass
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (held(mask[i]))
      local[0] += 1.0;
    else
      for (Fix *fix : rigid)
        if (mask[i] & fix->groupbit) {
          local[1] += 1.0;
          break;
        }
    if (!held(mask[i]) && added_mass(i) > 0.0) local[2] += 1.0;
  }
  MPI_Allreduce(local, total, 3, MPI_DOUBLE, MPI_SUM, world);
  any_held_or_rigid = total[0] + total[1] > 0.0;
  any = any_held_or_rigid || total[2] > 0.0;
  if (!log || comm->me != 0) return;
  for (const auto &id : unknown)
    error->warning(FLERR,
                   "{}: fix {} setforce was defined before the plugin was loaded (or, after a "
                   "clear, before the plugin's first style): its arguments are unknown, its atoms are not "
                   "taken as immovable",
                   who, id);
  if (any_held_or_rigid)
    utils::logmesg(lmp,
                   "{}: {:.0f} immovable atoms (infinite mass in contacts), {:.0f} in rigid bodies "
                   "(the body's mass)\n",
                   who, total[0], total[1]);
  if (total[2] > 0.0)
    utils::logmesg(lmp, "{}: {:.0f} spheres carry the fluid's added mass into their contacts (m + m_a)\n", who,
                   total[2]);
}

double ContactMass::added_mass(int i) const
{
  // As fix fluid/drag computes it: C_m (rho_f V).
  double mass = 0.0;
  for (const Carried &c : carried)
    if (atom->mask[i] & c.groupbit) mass += c.coefficient * (c.density * lubricated::sphere_volume(atom->radius[i]));
  return mass;
}

double ContactMass::along_normal(int i, double nx, double ny, double nz, double mass) const
{
  const int mask = atom->mask[i];
  if (held(mask)) return mass;
  for (Fix *fix : rigid)
    if (mask & fix->groupbit) return mass;
  // Per axis as fix fluid/drag solves: m + m_a near.mass[d].
  const double m = atom->rmass[i], radius = atom->radius[i];
  double axis[3] = {m, m, m};
  bool carries = false;
  for (const Carried &c : carried) {
    if (!(mask & c.groupbit)) continue;
    carries = true;
    const double m_a = c.coefficient * (c.density * lubricated::sphere_volume(radius));
    lubricated::WallAddedMass near;
    if (!c.walls->empty())
      near = lubricated::wall_added_mass(c.walls->data(), static_cast<int>(c.walls->size()), radius, atom->x[i]);
    for (int d = 0; d < 3; d++)
      axis[d] += m_a * near.mass[d];
  }
  if (!carries) return mass;
  return 1.0 / (nx * nx / axis[0] + ny * ny / axis[1] + nz * nz / axis[2]);
}

double ContactMass::own_fraction(int i, double mass) const
{
  const int mask = atom->mask[i];
  if (held(mask) || !(mass > 0.0)) return 1.0;
  for (Fix *fix : rigid)
    if (mask & fix->groupbit) return 1.0;
  return added_mass(i) > 0.0 ? atom->rmass[i] / mass : 1.0;
}

void ContactMass::fill(double *inverse)
{
  const int *mask = atom->mask;
  const double *rmass = atom->rmass;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    inverse[i] = held(mask[i]) ? 0.0 : 1.0 / (carried.empty() ? rmass[i] : rmass[i] + added_mass(i));
  for (Fix *fix : rigid) {
    int dim;
    const auto body = static_cast<const int *>(fix->extract("body", dim));
    const auto mass = static_cast<const double *>(fix->extract("masstotal", dim));
    if (!body || !mass) continue;    // a rigid fix without them: its atoms keep their own mass
    for (int i = 0; i < nlocal; i++)
      if ((mask[i] & fix->groupbit) && !held(mask[i]) && body[i] >= 0) inverse[i] = 1.0 / mass[body[i]];
  }
}

double LAMMPS_NS::smallest_sphere_radius(LAMMPS *lmp, const char *style, int groupbit)
{
  Atom *atom = lmp->atom;
  double smallest = INFINITY;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    if (!(atom->radius[i] > 0.0))
      lmp->error->one(FLERR, "{}: atom {} has diameter {} (allowed: > 0; a point particle has no contact or film)",
                      style, atom->tag[i], 2.0 * atom->radius[i]);
    smallest = std::min(smallest, atom->radius[i]);
  }
  double smallest_all = INFINITY;
  MPI_Allreduce(&smallest, &smallest_all, 1, MPI_DOUBLE, MPI_MIN, lmp->world);
  return smallest_all;
}
