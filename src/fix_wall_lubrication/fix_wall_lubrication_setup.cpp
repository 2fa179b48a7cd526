/* ----------------------------------------------------------------------
   fix wall/lubrication: the wall arguments and motion keywords, the checks of the spheres
   against the walls, the per-atom friction history and the restart (see
   doc/fix_wall_lubrication.rst; the walls' geometry and motion: lubricated/wall_geometry.h).
------------------------------------------------------------------------- */

#include "fix_wall_lubrication.h"

#include "contact_mass/contact_mass.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix wall/lubrication";

// xplane/yplane/zplane lo hi, or zcylinder R; then the motion keywords.
void FixWallLubrication::parse_walls(int narg, char **arg, int iwall)
{
  const std::string style = arg[iwall];
  int iarg;
  if (style == "zcylinder") {
    if (iwall + 2 > narg) error->all(FLERR, "{}: zcylinder needs its radius", STYLE);
    lub::WallSurface w;
    w.cylinder = true, w.axis = 2, w.side = -1;
    w.radius = utils::numeric(FLERR, arg[iwall + 1], false, lmp);
    if (!(w.radius > 0.0) || !std::isfinite(w.radius))
      error->all(FLERR, "{}: zcylinder radius = {} is out of range (allowed: 0 < R)", STYLE, arg[iwall + 1]);
    walls = {w};
    legacy_slots = {0};
    iarg = iwall + 2;
  } else {
    const int axis = style[0] - 'x';
    if (axis == 2 && domain->dimension == 2) error->all(FLERR, "{}: zplane is not allowed in 2d", STYLE);
    if (iwall + 3 > narg) error->all(FLERR, "{}: {} needs lo and hi positions", STYLE, style);
    walls.clear(), legacy_slots.clear();
    for (int side = 1; side >= -1; side -= 2) {
      const char *word = arg[iwall + (side == 1 ? 1 : 2)];
      if (strcmp(word, "NULL") == 0) continue;
      lub::WallSurface w;
      w.axis = axis, w.side = side;
      w.position = utils::numeric(FLERR, word, false, lmp);
      walls.push_back(w);
      legacy_slots.push_back(side == 1 ? 0 : 1);
    }
    if (walls.empty()) error->all(FLERR, "{}: both walls are NULL", STYLE);
    if (walls.size() == 2 && walls[0].position >= walls[1].position)
      error->all(FLERR, "{}: lo = {} must be below hi = {}", STYLE, walls[0].position, walls[1].position);
    iarg = iwall + 3;
  }
  history_size = HISTORY_PER_WALL * static_cast<int>(walls.size());
  parse_motion(narg, arg, iarg);
}

void FixWallLubrication::parse_motion(int narg, char **arg, int iarg)
{
  const bool cylinder = walls[0].cylinder, flat = domain->dimension == 2;
  auto dim_of = [&](const char *keyword, const char *word) {
    if (strlen(word) != 1 || word[0] < 'x' || word[0] > 'z')
      error->all(FLERR, "{}: {} dim = {} is unknown (allowed: x, y, z)", STYLE, keyword, word);
    if (flat && word[0] == 'z') error->all(FLERR, "{}: {} dim = z is not allowed in 2d", STYLE, keyword);
    return word[0] - 'x';
  };
  auto needs = [&](const char *keyword, int count) {
    if (iarg + count >= narg) error->all(FLERR, "{}: {} needs {} values", STYLE, keyword, count);
  };
  bool seen_translate = false, seen_side = false, seen_cavitation = false;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "translate") {
      needs("translate", 3);
      if (seen_translate) error->all(FLERR, "{}: translate given twice", STYLE);
      seen_translate = true;
      motion.translation = {utils::numeric(FLERR, arg[iarg + 1], false, lmp),
                            utils::numeric(FLERR, arg[iarg + 2], false, lmp),
                            utils::numeric(FLERR, arg[iarg + 3], false, lmp)};
      if (flat && motion.translation.z != 0.0)
        error->all(FLERR, "{}: translate vz = {} is not allowed in 2d (allowed: 0)", STYLE, motion.translation.z);
      iarg += 4;
    } else if (key == "wiggle") {
      needs("wiggle", 3);
      if (motion.wiggle_dim >= 0) error->all(FLERR, "{}: wiggle given twice", STYLE);
      motion.wiggle_dim = dim_of("wiggle", arg[iarg + 1]);
      motion.amplitude = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      motion.period = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
      if (!(motion.period > 0.0) || !std::isfinite(motion.period))
        error->all(FLERR, "{}: wiggle period = {} is out of range (allowed: 0 < period)", STYLE, arg[iarg + 3]);
      iarg += 4;
    } else if (key == "shear") {
      needs("shear", 2);
      if (motion.shear_dim >= 0) error->all(FLERR, "{}: shear given twice", STYLE);
      motion.shear_dim = dim_of("shear", arg[iarg + 1]);
      if (!cylinder && motion.shear_dim == walls[0].axis)
        error->all(FLERR,
                   "{}: shear dim = {} is normal to the wall (allowed: a dimension in the wall's plane; "
                   "translate or wiggle move a wall along its normal)",
                   STYLE, arg[iarg + 1]);
      motion.shear_speed = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      iarg += 3;
    } else if (key == "side") {
      needs("side", 1);
      if (!cylinder) error->all(FLERR, "{}: side applies to zcylinder only", STYLE);
      if (seen_side) error->all(FLERR, "{}: side given twice", STYLE);
      seen_side = true;
      const std::string value = arg[iarg + 1];
      if (value != "in" && value != "out")
        error->all(FLERR, "{}: side = {} is unknown (allowed: in, out)", STYLE, value);
      walls[0].side = value == "in" ? -1 : 1;
      iarg += 2;
    } else if (key == "cavitation") {
      needs("cavitation", 1);
      parse_cavitation(STYLE, arg[iarg + 1], seen_cavitation);
      iarg += 2;
    } else {
      error->all(FLERR,
                 "{}: unknown keyword '{}' after the wall arguments (allowed: translate, wiggle, shear, cavitation{})",
                 STYLE, key, cylinder ? ", side" : "");
    }
  }
}

// Time since the fix was defined: whole steps since step_origin at the time step motion_dt, the
// time before them in elapsed (an uninterrupted run and a restarted one get the same sums).
double FixWallLubrication::wall_time() const
{
  return elapsed + static_cast<double>(update->ntimestep - step_origin) * motion_dt;
}

// The time step changes (the timestep command after a run, fix dt/reset): the steps so far
// counted at the old one.
void FixWallLubrication::rebase_clock()
{
  if (update->dt == motion_dt) return;
  elapsed = wall_time();
  step_origin = update->ntimestep;
  motion_dt = update->dt;
}

std::string FixWallLubrication::describe_walls() const
{
  if (walls[0].cylinder)
    return fmt::format("zcylinder R = {} ({})", walls[0].radius, walls[0].side < 0 ? "inside" : "outside");
  std::string lo = "NULL", hi = "NULL";
  for (const lub::WallSurface &w : walls)
    (w.side == 1 ? lo : hi) = lub::detail::number(w.position);
  return fmt::format("lo = {}, hi = {}", lo, hi);
}

// At each run's set-up: every sphere fits inside a concave cylinder (its film radius would be
// infinite or negative), and the grid's eps_al = 0.75 dx / R_f stays <= 1 for the smallest
// film radius (a convex wall's R_f is below R).
void FixWallLubrication::check_sphere_sizes()
{
  const double smallest = smallest_sphere_radius(lmp, STYLE, groupbit);
  double largest = 0.0, largest_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) largest = std::max(largest, atom->radius[i]);
  MPI_Allreduce(&largest, &largest_all, 1, MPI_DOUBLE, MPI_MAX, world);
  double film_radius = smallest;
  for (const lub::WallSurface &w : walls) {
    if (largest_all > 0.0 && !w.holds(largest_all))
      error->all(FLERR, "{}: a sphere of radius {} does not fit inside the zcylinder of radius {} (allowed: R < {})",
                 STYLE, largest_all, w.radius, w.radius);
    if (std::isfinite(smallest)) film_radius = std::min(film_radius, w.film_radius(smallest));
  }
  const std::string problem = lub::validate_grid_for_radius(coeffs, film_radius);
  if (!problem.empty()) error->all(FLERR, "{}: {}", STYLE, problem);
}

// Once per run set-up: atoms whose centres lie behind a wall are left alone by it.
void FixWallLubrication::warn_behind()
{
  if (!update->setupflag) return;
  const lub::Vec3 shift = motion.displacement(wall_time());
  bigint count = 0, total = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit)
      for (const lub::WallSurface &w : walls)
        count += lub::wall_point(w, atom->x[i], 0.0, shift).gap < 0.0;
  MPI_Allreduce(&count, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total > 0 && comm->me == 0)
    error->warning(FLERR, "{}: {} atom(s) have their centre behind a wall ({}); the wall leaves them alone", STYLE,
                   total, describe_walls());
}

void FixWallLubrication::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[3] = {elapsed, static_cast<double>(step_origin), motion_dt};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(list), 1, fp);
}

void FixWallLubrication::restart(char *buf)
{
  double list[3];
  memcpy(list, buf, sizeof(list));
  elapsed = list[0];
  step_origin = static_cast<bigint>(list[1]);
  motion_dt = list[2];
}

void FixWallLubrication::grow_arrays(int nmax)
{
  memory->grow(history, nmax, history_size, "wall/lubrication:history");
}

void FixWallLubrication::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < history_size; k++)
    history[j][k] = history[i][k];
}

void FixWallLubrication::set_arrays(int i)
{
  for (int k = 0; k < history_size; k++)
    history[i][k] = 0.0;
}

int FixWallLubrication::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < history_size; k++)
    buf[k] = history[i][k];
  return history_size;
}

int FixWallLubrication::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < history_size; k++)
    history[nlocal][k] = buf[k];
  return history_size;
}

int FixWallLubrication::pack_restart(int i, double *buf)
{
  buf[0] = history_size + 1;
  for (int k = 0; k < history_size; k++)
    buf[k + 1] = history[i][k];
  return history_size + 1;
}

// This layout (history_size values), or the two-slot one of older restart files.
// A fix redefined without friction, rolling or shearfilm keeps no history: the file's is dropped
// (LAMMPS unpacks a restart's per-atom values into any fix of the same ID and style).
void FixWallLubrication::unpack_restart(int nlocal, int nth)
{
  if (!history) return;
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  const int stored = static_cast<int>(extra[nlocal][m]) - 1;
  const double *values = &extra[nlocal][m + 1];
  for (std::size_t w = 0; w < walls.size(); w++) {
    const int from = stored == history_size ? static_cast<int>(w) : legacy_slots[w];
    for (int k = 0; k < HISTORY_PER_WALL; k++)
      history[nlocal][w * HISTORY_PER_WALL + k] =
          (from + 1) * HISTORY_PER_WALL <= stored ? values[from * HISTORY_PER_WALL + k] : 0.0;
  }
}

int FixWallLubrication::size_restart(int /*i*/)
{
  return history_size + 1;
}

int FixWallLubrication::maxsize_restart()
{
  return history_size + 1;
}

double FixWallLubrication::memory_usage()
{
  return FixWallLubricationBase::memory_usage() +
         (history ? static_cast<double>(atom->nmax) * history_size * sizeof(double) : 0.0);
}
