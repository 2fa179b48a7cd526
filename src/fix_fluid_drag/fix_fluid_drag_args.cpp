/* ----------------------------------------------------------------------
   fix fluid/drag: its keywords (see doc/fix_fluid_drag.rst), parsed from one table

   fix ID group fluid/drag viscosity mu keyword value ...
     density rho_f | law stokes|schiller-naumann | hindrance none|richardson-zaki n|di-felice
     velocity ux uy uz (numbers or v_name) | flow velocity|affine | superficial yes|no | buoyancy gx gy gz
     bins nx ny nz | every N
     added_mass C_m | wall xplane|yplane|zplane lo hi (NULL or a number) | pressure yes|no | acceleration ax ay az (numbers or v_name)
     history yes|no | kernel basset|mei-adrian | window N_w | tail M | magnus yes|no | vorticity wx wy wz | saffman yes|no
     | rotation yes|no

   Each row of the table names a keyword, the number of values it needs at least and the
   action that reads them (and returns how many it read); a range check names the keyword,
   the value as given and the allowed range.
------------------------------------------------------------------------- */

#include "fix_fluid_drag.h"

#include "error.h"
#include "utils.h"

#include <string>

using namespace LAMMPS_NS;
namespace lub = lubricated;

static constexpr const char *STYLE = "Fix fluid/drag";

namespace LAMMPS_NS {
// The values after one keyword, with the conversions and checks the actions share.
struct FluidDragValues {
  FixFluidDrag &fix;
  LAMMPS *lmp;
  int narg;
  char **arg;
  int iarg;    // the keyword; its values follow

  const char *keyword() const { return arg[iarg]; }
  const char *text(int k) const { return arg[iarg + 1 + k]; }
  void need(int n) const
  {
    if (iarg + n >= narg) lmp->error->all(FLERR, "{}: missing value(s) for keyword {}", STYLE, keyword());
  }
  double number(int k) const { return utils::numeric(FLERR, text(k), false, lmp); }
  int integer(int k) const { return utils::inumeric(FLERR, text(k), false, lmp); }
  // LAMMPS's logical words (yes/no, on/off, true/false, 1/0); anything else names the keyword.
  bool yes_no(int k) const
  {
    const std::string word = utils::lowercase(text(k));
    if (word == "yes" || word == "on" || word == "true" || word == "1") return true;
    if (word == "no" || word == "off" || word == "false" || word == "0") return false;
    lmp->error->all(FLERR, "{}: {} must be yes or no, got '{}'", STYLE, keyword(), text(k));
    return false;
  }
  // lo <= value <= hi (or value = 0 where zero is allowed), else an ERROR "name = text is out of range".
  void check(bool valid, const char *name, int k, const char *allowed) const
  {
    if (!valid) lmp->error->all(FLERR, "{}: {} = {} is out of range (allowed: {})", STYLE, name, text(k), allowed);
  }
  void components(int k, FixFluidDrag::Component *c) const
  {
    for (int d = 0; d < 3; d++) {
      if (utils::strmatch(text(k + d), "^v_"))
        c[d].name = text(k + d) + 2;
      else
        c[d].value = number(k + d);
    }
  }
};

// One action per keyword; each returns the number of values it read.
struct FluidDragKeywords {
  using Values = FluidDragValues;

  static int viscosity(Values &a)
  {
    a.fix.model.viscosity = a.number(0);
    // The pair style's range: beyond it the history kernel's sums over- or underflow (NaN).
    const double mu = a.fix.model.viscosity;
    a.check(mu >= 1e-100 && mu <= 1e100, "viscosity", 0, "1e-100 <= mu_f <= 1e100");
    a.fix.have_viscosity = true;
    return 1;
  }
  static int density(Values &a)
  {
    const double rho = a.fix.model.density = a.number(0);
    a.check(rho == 0.0 || (rho >= 1e-100 && rho <= 1e100), "density", 0, "rho_f = 0 or 1e-100 <= rho_f <= 1e100");
    return 1;
  }
  static int law(Values &a)
  {
    const std::string law = a.text(0);
    if (law == "stokes")
      a.fix.model.law = lub::DragLaw::stokes;
    else if (law == "schiller-naumann")
      a.fix.model.law = lub::DragLaw::schiller_naumann;
    else
      a.lmp->error->all(FLERR, "{}: law must be stokes or schiller-naumann, got '{}'", STYLE, law);
    return 1;
  }
  static int hindrance(Values &a)
  {
    const std::string h = a.text(0);
    if (h == "none")
      a.fix.model.hindrance = lub::Hindrance::none;
    else if (h == "di-felice")
      a.fix.model.hindrance = lub::Hindrance::di_felice;
    else if (h == "richardson-zaki") {
      a.need(2);
      a.fix.model.hindrance = lub::Hindrance::richardson_zaki;
      const double n = a.fix.model.rz_exponent = a.number(1);
      a.check(n >= 1.0 && n <= 10.0, "richardson-zaki n", 1, "1 <= n <= 10");
      return 2;
    } else
      a.lmp->error->all(FLERR, "{}: hindrance must be none, richardson-zaki n or di-felice, got '{}'", STYLE, h);
    return 1;
  }
  static int velocity(Values &a)
  {
    a.components(0, a.fix.velocity);
    a.fix.velocity_given = true;
    return 3;
  }
  static int flow(Values &a)
  {
    const std::string flow = a.text(0);
    if (flow != "affine" && flow != "velocity")
      a.lmp->error->all(FLERR, "{}: flow must be affine or velocity, got '{}'", STYLE, flow);
    a.fix.affine_flow = flow == "affine";
    return 1;
  }
  static int acceleration(Values &a)
  {
    a.components(0, a.fix.acceleration);
    a.fix.acceleration_given = true;
    return 3;
  }
  static int vorticity(Values &a)
  {
    a.components(0, a.fix.vorticity);
    a.fix.vorticity_given = true;
    return 3;
  }
  static int buoyancy(Values &a)
  {
    for (int d = 0; d < 3; d++)
      a.fix.gravity[d] = a.number(d);
    return 3;
  }
  static int bins(Values &a)
  {
    double count = 1.0;    // in double: the product of three ints overflows an int
    for (int d = 0; d < 3; d++) {
      a.fix.nbins[d] = a.integer(d);
      a.check(a.fix.nbins[d] >= 1, "bins", d, ">= 1");
      count *= a.fix.nbins[d];
    }
    // Every rank holds two arrays of the bins (16 bytes a bin) and sums them over all ranks
    // in one MPI call; the limit keeps that within memory and the bin index within an int.
    if (count > FixFluidDrag::max_bins)
      a.lmp->error->all(FLERR,
                        "{}: bins {} {} {} = {:.0f} bins is out of range (allowed: nx ny nz <= {:.0f}, two "
                        "arrays of 16 bytes a bin on every MPI rank)",
                        STYLE, a.text(0), a.text(1), a.text(2), count, FixFluidDrag::max_bins);
    a.fix.bins_given = true;
    return 3;
  }
  static int every(Values &a)
  {
    a.fix.every = a.integer(0);
    a.check(a.fix.every >= 1, "every", 0, "N >= 1");
    return 1;
  }
  static int added_mass(Values &a)
  {
    const double c_m = a.fix.added_mass = a.number(0);
    a.check(c_m >= 0.0 && c_m <= 10.0, "added_mass C_m", 0, "0 <= C_m <= 10; 0.5 for a sphere");
    return 1;
  }
  static int wall(Values &a)
  {
    const std::string face = a.text(0);
    const int axis = face == "xplane" ? 0 : face == "yplane" ? 1 : face == "zplane" ? 2 : -1;
    if (axis < 0) a.lmp->error->all(FLERR, "{}: wall must be xplane, yplane or zplane, got '{}'", STYLE, face);
    for (const auto &w : a.fix.added_mass_walls)
      if (w.axis == axis) a.lmp->error->all(FLERR, "{}: wall {} is given twice", STYLE, face);
    bool any = false;
    for (int side = 0; side < 2; side++) {
      if (std::string(a.text(1 + side)) == "NULL") continue;
      a.fix.added_mass_walls.push_back({axis, a.number(1 + side)});
      any = true;
    }
    if (!any) a.lmp->error->all(FLERR, "{}: wall {} NULL NULL gives no wall", STYLE, face);
    return 3;
  }
  static int kernel(Values &a)
  {
    const std::string kernel = a.text(0);
    if (kernel == "basset")
      a.fix.finite_re = false;
    else if (kernel == "mei-adrian")
      a.fix.finite_re = true;
    else
      a.lmp->error->all(FLERR, "{}: kernel must be basset or mei-adrian, got '{}'", STYLE, kernel);
    return 1;
  }
  static int window(Values &a)
  {
    const int w = a.fix.history_window = a.integer(0);
    a.check(w >= 1 && w <= 1000, "window N_w", 0, "1 <= N_w <= 1000");
    return 1;
  }
  static int tail(Values &a)
  {
    const int m = a.fix.history_modes = a.integer(0);
    a.check(m == 0 || (m >= 8 && m <= 64), "tail M", 0, "0 or 8 <= M <= 64");
    return 1;
  }
  static int superficial(Values &a) { return a.fix.superficial = a.yes_no(0), 1; }
  static int pressure(Values &a) { return a.fix.pressure = a.yes_no(0), 1; }
  static int history(Values &a) { return a.fix.history = a.yes_no(0), 1; }
  static int magnus(Values &a) { return a.fix.magnus = a.yes_no(0), 1; }
  static int rotation(Values &a) { return a.fix.rotation = a.yes_no(0), 1; }
  static int saffman(Values &a) { return a.fix.saffman = a.yes_no(0), 1; }
};
}    // namespace LAMMPS_NS

namespace {
struct Keyword {
  const char *name;
  int values;    // at least; an action may read more (hindrance richardson-zaki n)
  int (*read)(FluidDragValues &);
};

using K = FluidDragKeywords;
const Keyword KEYWORDS[] = {
    {"viscosity", 1, K::viscosity},
    {"density", 1, K::density},
    {"law", 1, K::law},
    {"hindrance", 1, K::hindrance},
    {"velocity", 3, K::velocity},
    {"flow", 1, K::flow},
    {"superficial", 1, K::superficial},
    {"buoyancy", 3, K::buoyancy},
    {"bins", 3, K::bins},
    {"every", 1, K::every},
    {"added_mass", 1, K::added_mass},
    {"wall", 3, K::wall},
    {"pressure", 1, K::pressure},
    {"acceleration", 3, K::acceleration},
    {"history", 1, K::history},
    {"kernel", 1, K::kernel},
    {"window", 1, K::window},
    {"tail", 1, K::tail},
    {"magnus", 1, K::magnus},
    {"vorticity", 3, K::vorticity},
    {"saffman", 1, K::saffman},
    {"rotation", 1, K::rotation},
};

// "viscosity, density, ... or saffman", for the unknown-keyword message.
std::string keyword_list()
{
  std::string list;
  const int n = static_cast<int>(sizeof(KEYWORDS) / sizeof(KEYWORDS[0]));
  for (int k = 0; k < n; k++)
    list += (k == 0 ? "" : k == n - 1 ? " or " : ", ") + std::string(KEYWORDS[k].name);
  return list;
}
}    // namespace

void FixFluidDrag::parse(int narg, char **arg)
{
  int iarg = 3;
  while (iarg < narg) {
    const Keyword *found = nullptr;
    for (const Keyword &k : KEYWORDS)
      if (std::string(arg[iarg]) == k.name) found = &k;
    if (!found) error->all(FLERR, "{}: unknown keyword '{}' (expected {})", STYLE, arg[iarg], keyword_list());
    FluidDragValues values{*this, lmp, narg, arg, iarg};
    values.need(found->values);
    iarg += 1 + found->read(values);
  }
  check_keywords();
}

// What one keyword asks of the others.
void FixFluidDrag::check_keywords()
{
  if (!have_viscosity) error->all(FLERR, "{}: the viscosity keyword is required", STYLE);
  if (affine_flow && velocity_given)
    error->all(FLERR, "{}: flow affine and the velocity keyword both give the fluid velocity: give one", STYLE);
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
