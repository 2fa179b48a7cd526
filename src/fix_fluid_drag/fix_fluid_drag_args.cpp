/* ----------------------------------------------------------------------
   fix fluid/drag: its keywords (see doc/fix_fluid_drag.rst)

   fix ID group fluid/drag viscosity mu keyword value ...
     density rho_f | law stokes|schiller-naumann | hindrance none|richardson-zaki n|di-felice
     velocity ux uy uz (numbers or v_name) | superficial yes|no | buoyancy gx gy gz
     bins nx ny nz | every N
     added_mass C_m | wall xplane|yplane|zplane lo hi (NULL or a number) | pressure yes|no | acceleration ax ay az (numbers or v_name)
     history yes|no | kernel basset|mei-adrian | window N_w | tail M | magnus yes|no | vorticity wx wy wz | saffman yes|no
------------------------------------------------------------------------- */

#include "fix_fluid_drag.h"

#include "error.h"
#include "utils.h"

using namespace LAMMPS_NS;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix fluid/drag";

void FixFluidDrag::parse(int narg, char **arg)
{
  bool have_viscosity = false;
  auto need = [&](int iarg, int n) {
    if (iarg + n >= narg) error->all(FLERR, "{}: missing value(s) for keyword {}", STYLE, arg[iarg]);
  };
  auto number = [&](int iarg) { return utils::numeric(FLERR, arg[iarg], false, lmp); };
  auto yes_no = [&](int iarg) { return utils::logical(FLERR, arg[iarg], false, lmp) == 1; };
  auto components = [&](int iarg, Component *c) {
    for (int d = 0; d < 3; d++) {
      if (utils::strmatch(arg[iarg + d], "^v_"))
        c[d].name = arg[iarg + d] + 2;
      else
        c[d].value = number(iarg + d);
    }
  };
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "viscosity") {
      need(iarg, 1);
      model.viscosity = number(iarg + 1);
      // The pair style's range: beyond it the history kernel's sums over- or underflow (NaN).
      if (!(model.viscosity >= 1e-100 && model.viscosity <= 1e100))
        error->all(FLERR, "{}: viscosity = {} is out of range (allowed: 1e-100 <= mu_f <= 1e100)", STYLE,
                   arg[iarg + 1]);
      have_viscosity = true;
      iarg += 2;
    } else if (key == "density") {
      need(iarg, 1);
      model.density = number(iarg + 1);
      if (!(model.density == 0.0 || (model.density >= 1e-100 && model.density <= 1e100)))
        error->all(FLERR, "{}: density = {} is out of range (allowed: rho_f = 0 or 1e-100 <= rho_f <= 1e100)", STYLE,
                   arg[iarg + 1]);
      iarg += 2;
    } else if (key == "law") {
      need(iarg, 1);
      const std::string law = arg[iarg + 1];
      if (law == "stokes")
        model.law = lub::DragLaw::stokes;
      else if (law == "schiller-naumann")
        model.law = lub::DragLaw::schiller_naumann;
      else
        error->all(FLERR, "{}: law must be stokes or schiller-naumann, got '{}'", STYLE, law);
      iarg += 2;
    } else if (key == "hindrance") {
      need(iarg, 1);
      const std::string h = arg[iarg + 1];
      iarg += 2;
      if (h == "none")
        model.hindrance = lub::Hindrance::none;
      else if (h == "di-felice")
        model.hindrance = lub::Hindrance::di_felice;
      else if (h == "richardson-zaki") {
        need(iarg - 1, 1);
        model.hindrance = lub::Hindrance::richardson_zaki;
        model.rz_exponent = number(iarg);
        if (!(model.rz_exponent >= 1.0 && model.rz_exponent <= 10.0))
          error->all(FLERR, "{}: richardson-zaki n = {} is out of range (allowed: 1 <= n <= 10)", STYLE, arg[iarg]);
        iarg += 1;
      } else
        error->all(FLERR, "{}: hindrance must be none, richardson-zaki n or di-felice, got '{}'", STYLE, h);
    } else if (key == "velocity") {
      need(iarg, 3);
      components(iarg + 1, velocity);
      iarg += 4;
    } else if (key == "acceleration") {
      need(iarg, 3);
      components(iarg + 1, acceleration);
      acceleration_given = true;
      iarg += 4;
    } else if (key == "superficial") {
      need(iarg, 1);
      superficial = yes_no(iarg + 1);
      iarg += 2;
    } else if (key == "buoyancy") {
      need(iarg, 3);
      for (int d = 0; d < 3; d++)
        gravity[d] = number(iarg + 1 + d);
      iarg += 4;
    } else if (key == "bins") {
      need(iarg, 3);
      for (int d = 0; d < 3; d++) {
        nbins[d] = utils::inumeric(FLERR, arg[iarg + 1 + d], false, lmp);
        if (nbins[d] < 1) error->all(FLERR, "{}: bins {} is out of range (allowed: >= 1)", STYLE, nbins[d]);
      }
      bins_given = true;
      iarg += 4;
    } else if (key == "every") {
      need(iarg, 1);
      every = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (every < 1) error->all(FLERR, "{}: every = {} is out of range (allowed: N >= 1)", STYLE, every);
      iarg += 2;
    } else if (key == "added_mass") {
      need(iarg, 1);
      added_mass = number(iarg + 1);
      if (!(added_mass >= 0.0 && added_mass <= 10.0))
        error->all(FLERR, "{}: added_mass C_m = {} is out of range (allowed: 0 <= C_m <= 10; 0.5 for a sphere)", STYLE,
                   arg[iarg + 1]);
      iarg += 2;
    } else if (key == "wall") {
      need(iarg, 3);
      const std::string face = arg[iarg + 1];
      const int axis = face == "xplane" ? 0 : face == "yplane" ? 1 : face == "zplane" ? 2 : -1;
      if (axis < 0) error->all(FLERR, "{}: wall must be xplane, yplane or zplane, got '{}'", STYLE, face);
      for (const auto &w : added_mass_walls)
        if (w.axis == axis) error->all(FLERR, "{}: wall {} is given twice", STYLE, face);
      bool any = false;
      for (int side = 0; side < 2; side++) {
        if (std::string(arg[iarg + 2 + side]) == "NULL") continue;
        added_mass_walls.push_back({axis, number(iarg + 2 + side)});
        any = true;
      }
      if (!any) error->all(FLERR, "{}: wall {} NULL NULL gives no wall", STYLE, face);
      iarg += 4;
    } else if (key == "pressure") {
      need(iarg, 1);
      pressure = yes_no(iarg + 1);
      iarg += 2;
    } else if (key == "history") {
      need(iarg, 1);
      history = yes_no(iarg + 1);
      iarg += 2;
    } else if (key == "kernel") {
      need(iarg, 1);
      const std::string kernel = arg[iarg + 1];
      if (kernel == "basset")
        finite_re = false;
      else if (kernel == "mei-adrian")
        finite_re = true;
      else
        error->all(FLERR, "{}: kernel must be basset or mei-adrian, got '{}'", STYLE, kernel);
      iarg += 2;
    } else if (key == "window") {
      need(iarg, 1);
      history_window = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (history_window < 1 || history_window > 1000)
        error->all(FLERR, "{}: window N_w = {} is out of range (allowed: 1 <= N_w <= 1000)", STYLE, history_window);
      iarg += 2;
    } else if (key == "tail") {
      need(iarg, 1);
      history_modes = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (history_modes != 0 && (history_modes < 8 || history_modes > 64))
        error->all(FLERR, "{}: tail M = {} is out of range (allowed: 0 or 8 <= M <= 64)", STYLE, history_modes);
      iarg += 2;
    } else if (key == "vorticity") {
      need(iarg, 3);
      components(iarg + 1, vorticity);
      vorticity_given = true;
      iarg += 4;
    } else if (key == "saffman") {
      need(iarg, 1);
      saffman = yes_no(iarg + 1);
      iarg += 2;
    } else if (key == "magnus") {
      need(iarg, 1);
      magnus = yes_no(iarg + 1);
      iarg += 2;
    } else {
      error->all(FLERR,
                 "{}: unknown keyword '{}' (expected viscosity, density, law, hindrance, velocity, "
                 "superficial, buoyancy, bins, every, added_mass, wall, pressure, acceleration, history, "
                 "kernel, window, tail, magnus, vorticity or saffman)",
                 STYLE, key);
    }
  }
  if (!have_viscosity) error->all(FLERR, "{}: the viscosity keyword is required", STYLE);
  if (finite_re && !history) error->all(FLERR, "{}: kernel mei-adrian needs history yes", STYLE);
  if ((gravity[0] != 0.0 || gravity[1] != 0.0 || gravity[2] != 0.0) && model.density == 0.0)
    error->all(FLERR, "{}: buoyancy needs the fluid density (density keyword)", STYLE);
  if (fluid_inertia() && model.density == 0.0)
    error->all(FLERR, "{}: added_mass, pressure, history, magnus and saffman need the fluid density (density keyword)",
               STYLE);
  if (!added_mass_walls.empty() && !(added_mass > 0.0))
    error->all(FLERR, "{}: wall (the added mass's near-wall increase) needs added_mass C_m > 0", STYLE);
  bool varying = false;
  for (const auto &c : velocity)
    varying = varying || !c.name.empty();
  if (varying && (added_mass > 0.0 || pressure || history) && !acceleration_given)
    error->all(FLERR,
               "{}: a fluid velocity given by variables needs the acceleration keyword (Du_f/Dt) "
               "with added_mass, pressure or history",
               STYLE);
  if (model.density == 0.0 && model.law == lub::DragLaw::schiller_naumann)
    model.law = lub::DragLaw::stokes;    // Re = 0 without a fluid density
  if (saffman && !vorticity_given)
    error->all(FLERR, "{}: saffman yes needs the vorticity keyword (the fluid's curl u_f; without it the lift is zero)",
               STYLE);
  if (needs_fraction() && !bins_given)
    error->all(FLERR, "{}: hindrance and superficial need the bins keyword for the solid fraction", STYLE);
}
