/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot (see doc/pair_lubricated_springdashpot.rst)
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"

#include "unit_style/unit_style.h"
#include "vector_pairs.h"

#include "fix_contact_history/fix_contact_history.h"
#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_step_velocity/fix_step_velocity.h"
#include "fix_lubricated_wall/fix_lubricated_wall.h"
#include "lubricated/check_setup.h"
#include "lubricated/contact_network.h"
#include "lubricated/contact_network_message.h"
#include "lubricated/contact_network_ranks.h"
#include "lubricated/film_budget.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

using namespace LAMMPS_NS;
namespace lub = lubricated;

static constexpr const char *STYLE = "Pair style lubricated/springdashpot";

PairLubricatedSpringDashpot::PairLubricatedSpringDashpot(LAMMPS *lmp) : Pair(lmp), contact_mass(lmp)
{
  ContactMass::watch_setforce(lmp);    // again after a `clear`
  single_enable = 1;
  single_extra = 3;    // contact force, lubrication force, normalised gap
  svector = new double[single_extra];
  // compute pair: the pairs the last evaluation selected and, of those, the film-only ones.
  nextra = 2;
  pvector = new double[nextra]();
  finitecutflag = 1;
  restartinfo = 1;
  writedata = 1;
  // The film budget: scales forward, loads reverse (1 value per atom); the contact masses
  // forward (1); the contact-network check: its sums both ways (lub::network_values).
  comm_forward = comm_reverse = lub::network_values;
  // The contact-history fix's place in the fix list, held from here by a placeholder that the
  // history replaces at the first run with friction (as LAMMPS's granular styles do): fixes
  // defined after the pair style that add or remove atoms in pre_exchange (deposit, evaporate)
  // then run after the history is stored from the list, not before (it read their atoms then).
  history_id = "LUBRICATED_HISTORY_" + std::to_string(instance_me);
  modify->add_fix(history_slot_id() + " all DUMMY");
}

PairLubricatedSpringDashpot::~PairLubricatedSpringDashpot()
{
  delete[] svector;
  delete[] pvector;
  // The history fix or its placeholder goes with the pair style (modify outlives force at shutdown).
  for (const std::string &id : {history_id, history_slot_id()})
    if (modify->get_fix_by_id(id)) modify->delete_fix(id);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairLubricatedSpringDashpot::allocate()
{
  allocated = 1;
  const int n = ntypes_alloc = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++)
      setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  coeffs.assign((n + 1) * (n + 1), lub::Coefficients());
  models.assign((n + 1) * (n + 1), lub::ContactModel());
  max_reach.assign((n + 1) * (n + 1), 0.0);
  network_load.assign((n + 1) * (n + 1), 0.0);
  network_bound.assign((n + 1) * (n + 1), 0.0);
  maxrad.assign(n + 1, 0.0);
  cutoff_given.assign((n + 1) * (n + 1), 0.0);
}

// pair_style lubricated/springdashpot [vector yes|no] [limit atom|pair] [trim yes|no]
void PairLubricatedSpringDashpot::settings(int narg, char **arg)
{
  require_supported_units(lmp, STYLE);
  vector_enabled = true;
  limit_per_atom = true;
  trim_enabled = true;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (key != "vector" && key != "limit" && key != "trim")
      error->all(FLERR,
                 "{}: unknown keyword '{}' (allowed: vector yes|no, limit atom|pair, trim yes|no; "
                 "coefficients go in pair_coeff)",
                 STYLE, key);
    const char *allowed = key == "limit" ? "atom or pair" : "yes or no";
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value ({})", STYLE, key, allowed);
    const std::string value = arg[iarg + 1];
    if (key == "limit") {
      if (value != "atom" && value != "pair")
        error->all(FLERR, "{}: limit = {} is not allowed (atom or pair)", STYLE, value);
      limit_per_atom = value == "atom";
      continue;
    }
    if (value != "yes" && value != "no") error->all(FLERR, "{}: {} = {} is not allowed (yes or no)", STYLE, key, value);
    (key == "vector" ? vector_enabled : trim_enabled) = value == "yes";
  }
}

// One int: bit 0 vector yes, bit 1 limit pair, bit 2 trim no, bit 3 a cutoff follows each type
// pair's coefficients (files written before `limit`, `trim` or `cutoff` read as atom, yes and
// cutoffs from the radii).
void PairLubricatedSpringDashpot::write_restart_settings(FILE *fp)
{
  const int flag =
      (vector_enabled ? 1 : 0) | (limit_per_atom ? 0 : 2) | (trim_enabled ? 0 : 4) | (any_cutoff_given() ? 8 : 0);
  fwrite(&flag, sizeof(int), 1, fp);
}

void PairLubricatedSpringDashpot::read_restart_settings(FILE *fp)
{
  int flag = 1;
  if (comm->me == 0) utils::sfread(FLERR, &flag, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&flag, 1, MPI_INT, 0, world);
  vector_enabled = (flag & 1) != 0;
  limit_per_atom = (flag & 2) == 0;
  trim_enabled = (flag & 4) == 0;
  restart_cutoffs = (flag & 8) != 0;
}

bool PairLubricatedSpringDashpot::any_cutoff_given() const
{
  return std::any_of(cutoff_given.begin(), cutoff_given.end(), [](double c) { return c > 0.0; });
}

// pair_coeff I J e_d [ncontact N | tcontact t_c] [viscosity mu_f] [activation eps_al | grid dx] [cutoff r_c]
//                    [saturation eps_1] [release eps_2]
void PairLubricatedSpringDashpot::coeff(int narg, char **arg)
{
  if (narg < 3) error->all(FLERR, "{}: pair_coeff needs I J e_d [keyword value ...]", STYLE);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  std::vector<std::string> words(arg + 2, arg + narg);
  // cutoff: the pair style's own keyword (the list's, as pair_style granular's); the rest is the
  // model's, shared with the walls.
  double cutoff = 0.0;
  std::size_t k = 1;    // keywords at 1, 3, ... (each takes one value)
  while (k < words.size()) {
    if (words[k] != "cutoff") {
      k += 2;
      continue;
    }
    if (k + 1 >= words.size())
      error->all(FLERR, "{} pair_coeff {} {}: missing value for keyword cutoff", STYLE, arg[0], arg[1]);
    if (!lub::detail::to_number(words[k + 1], cutoff) || !(cutoff > 0.0))
      error->all(FLERR, "{} pair_coeff {} {}: cutoff = {} is not allowed (a distance > 0)", STYLE, arg[0], arg[1],
                 words[k + 1]);
    words.erase(words.begin() + k, words.begin() + k + 2);
  }
  lub::Coefficients c;
  std::string problem = lub::parse_coefficients(words, 0, c);
  if (problem.rfind("unknown keyword", 0) == 0) problem += "; pair_coeff also takes cutoff";
  if (!problem.empty()) error->all(FLERR, "{} pair_coeff {} {}: {}", STYLE, arg[0], arg[1], problem);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      coeffs[index(i, j)] = c;
      coeffs[index(j, i)] = c;
      cutoff_given[index(i, j)] = cutoff_given[index(j, i)] = cutoff;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "{}: incorrect atom types in pair_coeff {} {}", STYLE, arg[0], arg[1]);
}

void PairLubricatedSpringDashpot::init_style()
{
  require_supported_units(lmp, STYLE);
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "{} requires atom_style sphere (per-atom radius and rmass)", STYLE);
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "{} requires ghost atoms to store velocity: use comm_modify vel yes", STYLE);

  const int n = atom->ntypes;
  any_wet = any_tangential = false;
  network_check = network_warned = false;    // set by init_one (set_network_loads)
  network_next = 0;                          // the first step of the run
  bool any_friction = false, any_shear_film = false;
  std::set<std::string> advice;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j]) continue;
      lub::settle_contact_time(coeffs[index(i, j)], update->dt);
      coeffs[index(j, i)] = coeffs[index(i, j)];
      const lub::Coefficients &c = coeffs[index(i, j)];
      const lub::SetupCheck check = lub::check_setup(c, lub::Partner::particle, update->dt);
      if (!check.error.empty()) error->all(FLERR, "{} types {} {}: {}", STYLE, i, j, check.error);
      advice.insert(check.warnings.begin(), check.warnings.end());
      any_wet = any_wet || c.wet();
      any_tangential = any_tangential || c.tangential();
      any_friction = any_friction || c.friction > 0.0;
      any_shear_film = any_shear_film || (c.wet() && c.shear_film());
    }
  if (any_tangential && !(atom->omega_flag && atom->torque_flag))
    error->all(FLERR,
               "{} with friction, rolling or shearfilm requires per-atom omega and torque "
               "(atom_style sphere)",
               STYLE);
  // Friction needs the tangential elongation of every contact, kept by a fix of our own
  // that follows atoms across neighbor-list rebuilds, ranks and restart files.
  if (any_friction && !history) {
    const std::string command = history_id + " all LUBRICATED_HISTORY 3";
    history = dynamic_cast<FixContactHistory *>(modify->get_fix_by_id(history_slot_id())
                                                    ? modify->replace_fix(history_slot_id(), command, 1)
                                                    : modify->add_fix(command));
    if (!history) error->all(FLERR, "{}: could not create its contact-history fix", STYLE);
    // Friction added after a run: the neighbor list of that run is kept (init_list is not
    // called again while the requests are unchanged) and is the one the history follows.
    if (list) history->set_list(list);
  }
  // With a history the list is trimmed before the history is laid onto its entries.
  if (history) history->before_mapping = [this]() { trim_list_to_reach(); };
  if (!any_friction && history) {
    modify->replace_fix(history_id, history_slot_id() + " all DUMMY", 1);
    history = nullptr;
  }
  if (comm->me == 0)
    for (const auto &msg : advice)
      if (!msg.empty()) error->warning(FLERR, "{}: {}", STYLE, msg);
  // Under pair_style hybrid each instance of the style keeps its own film budget, and fix
  // wall/lubrication joins none where there are several (fix_lubricated_wall.cpp).
  // (pair_match gives the only instance for any nsub, and each of several for its own.)
  if (any_wet && comm->me == 0 && utils::strmatch(force->pair_style, "^hybrid") &&
      force->pair_match("lubricated/springdashpot", 1, 1) != force->pair_match("lubricated/springdashpot", 1, 2))
    error->warning(FLERR,
                   "{}: several instances under pair_style hybrid: each keeps the many-body film "
                   "budget of its own pairs, and fix wall/lubrication joins none, so a sphere with films "
                   "of two is not held within one budget (limit atom); give every type pair to one "
                   "instance, whose pair_coeff takes coefficients per type pair",
                   STYLE);

  // Under fix nve/sphere/midpoint forces are evaluated with the extrapolated V~; the step-exact
  // integration needs the velocity over the last step instead, which that fix provides.
  midpoint = FixNVESphereMidpoint::in_use(lmp, STYLE);
  // Under velocity Verlet a run's set-up continues the last run's steps where it can.
  step_velocity = midpoint ? nullptr : FixStepVelocity::find_or_create(lmp);
  verlet_velocities = step_velocity && step_velocity->integrated_by_nve_sphere();

  // The vectorised loops need the step velocity in v and exactly integrated normal forces;
  // type pairs with other coefficients are grouped by type pair (vector_forces).
  vector_loops = vector_enabled && !any_tangential && !midpoint;
  // With friction or rolling, the pairs apart over a step feel the normal and shear films
  // alone: they take a vectorised film loop too; and the sustained frictional contacts theirs.
  film_loops = vector_enabled && any_tangential && !midpoint;
  uniform_models = true;
  double first[lub::Coefficients::packed_size], other[lub::Coefficients::packed_size];
  coeffs[index(1, 1)].pack(first);
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j]) continue;
      coeffs[index(i, j)].pack(other);
      vector_loops = vector_loops && coeffs[index(i, j)].exact_contact;
      film_loops = film_loops && coeffs[index(i, j)].exact_contact;
      uniform_models = uniform_models && std::equal(first, first + lub::Coefficients::packed_size, other);
    }
  if (vector_loops && comm->me == 0)
    utils::logmesg(lmp,
                   "{}: pairs in sustained contact{}, and contacts that start or end within a step (without "
                   "legendre), take vectorised loops\n",
                   STYLE, any_wet ? " or apart over a step" : "");
  if (film_loops && any_wet && comm->me == 0)
    utils::logmesg(lmp, "{}: pairs apart over a step take the vectorised film loop\n", STYLE);
  if (film_loops && history && comm->me == 0)
    utils::logmesg(lmp,
                   "{}: pairs in sustained frictional contact take a vectorised loop, and contacts that start or "
                   "end within a step (without legendre) another\n",
                   STYLE);

  // The many-body film budget covers the films of these pairs and of the wet walls.
  walls.clear();
  bool wet_walls = false;
  for (Fix *ifix : modify->get_fix_list()) {    // fix wall/lubrication and wall/lubrication/region
    auto wall = dynamic_cast<FixLubricatedWall *>(ifix);
    if (!wall) continue;
    walls.push_back(wall);
    wet_walls = wet_walls || wall->wet();
  }
  film_budget = limit_per_atom && (any_wet || wet_walls);
  shear_records = film_budget && any_shear_film;    // the shear films share the budget
  if (!film_budget) scale_of_atom.clear();
  if ((any_wet || wet_walls) && comm->me == 0)
    utils::logmesg(lmp, "{}: {}\n", STYLE,
                   film_budget ? "films within each sphere's many-body budget (limit atom)"
                               : "each film within its own cap only (limit pair)");

  // Immovable atoms and rigid bodies, found anew at every run (fixes and groups may change).
  contact_mass.init(STYLE, true);
  inverse_mass_on = contact_mass.active();

  // A dry model acts only in contact: a radius-based list is enough and cheapest. The film
  // acts beyond contact, where radius-based lists lose pairs on rebuild (LAMMPS PR #4685),
  // so a wet model asks for a list with per-type cutoffs that cover the whole film.
  neighbor->add_request(this, any_wet ? NeighConst::REQ_DEFAULT : NeighConst::REQ_SIZE);

  // Point particles are refused; with a grid spacing the smallest spheres have the largest
  // eps_al (at most 1, as activation).
  const double r_min_all = smallest_sphere_radius(lmp, STYLE, ~0);
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      const std::string problem = setflag[i][j] ? lub::validate_grid_for_radius(coeffs[index(i, j)], r_min_all) : "";
      if (!problem.empty()) error->all(FLERR, "{} types {} {}: {}", STYLE, i, j, problem);
    }

  // Largest radius per type: atoms present now, and those fix pour/deposit may insert.
  std::vector<double> local(n + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    local[atom->type[i]] = MAX(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
  for (auto &ifix : modify->get_fix_list())
    for (int t = 1; t <= n; t++) {
      int itype = t;
      auto r = static_cast<double *>(ifix->extract("radius", itype));
      if (r && *r > maxrad[t]) maxrad[t] = *r;
    }
}

void PairLubricatedSpringDashpot::init_list(int id, NeighList *ptr)
{
  Pair::init_list(id, ptr);
  if (history) history->set_list(ptr);
}

double PairLubricatedSpringDashpot::init_one(int i, int j)
{
  if (!setflag[i][j]) error->all(FLERR, "{}: coefficients for atom types {} {} are not set (no mixing)", STYLE, i, j);
  const lub::Coefficients &c = coeffs[index(i, j)];
  models[index(i, j)] = models[index(j, i)] = lub::make_contact_model(c, lub::Partner::particle, update->dt);
  set_network_loads(i, j);
  if (comm->me == 0) {
    // Report what was derived (k and c per unit reduced mass, the contact resolution).
    const lub::SetupCheck check = lub::check_setup(c, lub::Partner::particle, update->dt);
    utils::logmesg(lmp, "{} types {} {}: {}\n", STYLE, i, j, check.description);
    if (!check.tangential.empty()) utils::logmesg(lmp, "{} types {} {}: {}\n", STYLE, i, j, check.tangential);
  }

  const double reach = largest_film_reach(i, j);
  max_reach[index(i, j)] = max_reach[index(j, i)] = reach;
  // pair_coeff cutoff replaces the one from the radii (follow_radii checks it covers them).
  const double given = cutoff_given[index(i, j)];
  return given > 0.0 ? given : maxrad[i] + maxrad[j] + reach;
}

// The film of the largest pair of types i, j (maxrad) reaches farthest; 0 for a dry pair.
double PairLubricatedSpringDashpot::largest_film_reach(int i, int j) const
{
  if (!coeffs[index(i, j)].wet() || maxrad[i] <= 0.0 || maxrad[j] <= 0.0) return 0.0;
  return models[index(i, j)].normal.reach(lub::film_radius_pair(maxrad[i], maxrad[j]).value);
}

void PairLubricatedSpringDashpot::update_models()
{
  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++)
      if (setflag[i][j]) {
        models[index(i, j)] = models[index(j, i)] =
            lub::make_contact_model(coeffs[index(i, j)], lub::Partner::particle, update->dt, &models[index(i, j)]);
        set_network_loads(i, j);
      }
}

// Load of a sustained contact of these types (contact_network.h): kappa + 2 gamma of its per-step
// constants, and the larger of it and the tangential spring's (friction) for the upper bound.
void PairLubricatedSpringDashpot::set_network_loads(int i, int j)
{
  double load, bound;
  lub::network_loads(models[index(i, j)], update->dt, load, bound);
  network_load[index(i, j)] = network_load[index(j, i)] = load;
  network_bound[index(i, j)] = network_bound[index(j, i)] = bound;
  network_check = network_check || bound > lub::network_check_load;
}

// A new time step: the per-step constants follow it; k and c stay (t_c settled at the first run,
// lubricated/coefficients.h settle_contact_time).
void PairLubricatedSpringDashpot::reset_dt()
{
  update_models();
}

void PairLubricatedSpringDashpot::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  trim_list_if_built();
  // A set-up that continues the last run evaluates as its last step did (fix_step_velocity.h);
  // not with rigid bodies or immovable atoms, whose velocities the reconstruction does not know.
  continued = step_velocity && step_velocity->continues() && !contact_mass.holds_or_rigid();
  step_velocities_used = !update->setupflag || continued;
  if (update->setupflag) find_network_walls();
  if (inverse_mass_on && (neighbor->ago == 0 || update->setupflag)) update_inverse_mass();
  if (!film_budget)
    film_budget_now = false;
  else if (neighbor->ago == 0 || update->setupflag || update->dt > film_bound_dt)
    // The bounds grow with dt (film_budget.h): those of a larger step hold for a smaller one,
    // so adaptive time stepping recomputes them only where dt grows past theirs.
    film_budget_now = films_can_exceed_budget();
  if (film_budget_now) begin_film_budget();
  selected_pairs = film_only_pairs = 0;
  // A scene pays only for what it uses: one loop per combination.
  if (any_tangential) {
    if (any_wet)
      film_loops && (!update->setupflag || continued) ? eval<true, true, true>() : eval<true, true>();
    else
      film_loops && (!update->setupflag || continued) ? eval<false, true, true>() : eval<false, true>();
  } else {
    // The vectorised loops for steps (a run's set-up evaluates with full-step velocities, unless
    // it continues the last run's steps).
    const bool vectorised = vector_loops && (!update->setupflag || continued);
    if (any_wet)
      vectorised ? eval<true, false, true>() : eval<true, false>();
    else
      vectorised ? eval<false, false, true>() : eval<false, false>();
  }
  if (film_budget_now) finish_film_budget();
  pvector[0] = static_cast<double>(selected_pairs);
  pvector[1] = static_cast<double>(film_only_pairs);
  if (vflag_fdotr) virial_fdotr_compute();
}

double PairLubricatedSpringDashpot::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                                           double /*factor_lj*/, double &fforce)
{
  fforce = 0.0;
  svector[0] = svector[1] = 0.0;
  const double radi = atom->radius[i], radj = atom->radius[j];
  const double radsum = radi + radj;
  const double r = std::sqrt(rsq);
  const lub::FilmRadius film = lub::film_radius_pair(radi, radj);
  const double lub_radius = film.value;
  svector[2] = (r - radsum) / lub_radius;
  const lub::NormalModel &model = models[index(itype, jtype)].normal;
  if (rsq == 0.0) return 0.0;

  // The velocities the last evaluation took: after a step of fix nve/sphere (or a set-up that
  // continued one) velocity Verlet's v^(n+1/2), while compute pair/local and dumps see an owned
  // atom's v^(n+1) = v^(n+1/2) + dt/2 f/m (f that evaluation's) and a ghost's v^(n+1/2) of the
  // step's communication; after a fresh set-up, or under other integrators, v as it is.
  double **x = atom->x, **v = atom->v, **f = atom->f;
  // A set-up that continued took the velocities fix LUBRICATED_STEP_VELOCITY restored (owned
  // and ghost atoms), which it keeps until the next step.
  const bool half_kick = verlet_velocities && step_velocities_used;
  double **restored = continued && step_velocity ? step_velocity->velocity() : nullptr;
  const double dtf = 0.5 * update->dt * force->ftm2v;
  auto step_v = [&](int k, int d) {
    if (restored) return restored[k][d];
    return half_kick && k < atom->nlocal ? v[k][d] - dtf * f[k][d] / atom->rmass[k] : v[k][d];
  };
  double u_n = 0.0;
  for (int d = 0; d < 3; d++)
    u_n += (step_v(i, d) - step_v(j, d)) * (x[i][d] - x[j][d]);
  u_n /= r;
  if (!model.acts(r - radsum, lub_radius, u_n)) return 0.0;
  const double m_e = inverse_mass_on ? lub::reduced_mass_of_inverses(inverse_mass[i], inverse_mass[j])
                                     : lub::reduced_mass(atom->rmass[i], atom->rmass[j]);
  if (m_e == 0.0) return 0.0;
  const lub::NormalForce fn = lub::normal_force(model, r - radsum, film, m_e, u_n);
  fforce = fn.total() / r;
  svector[0] = fn.contact;
  svector[1] = fn.lubrication;
  return fn.energy;
}

void PairLubricatedSpringDashpot::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  double buf[lub::Coefficients::packed_size];
  const bool cutoffs = any_cutoff_given();    // as write_restart_settings flags it
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      coeffs[index(i, j)].pack(buf);
      fwrite(buf, sizeof(double), lub::Coefficients::packed_size, fp);
      if (cutoffs) fwrite(&cutoff_given[index(i, j)], sizeof(double), 1, fp);
    }
}

void PairLubricatedSpringDashpot::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  double buf[lub::Coefficients::packed_size];
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      if (me == 0) utils::sfread(FLERR, buf, sizeof(double), lub::Coefficients::packed_size, fp, nullptr, error);
      MPI_Bcast(buf, lub::Coefficients::packed_size, MPI_DOUBLE, 0, world);
      coeffs[index(i, j)].unpack(buf);
      coeffs[index(j, i)].unpack(buf);
      if (!restart_cutoffs) continue;
      double cutoff = 0.0;
      if (me == 0) utils::sfread(FLERR, &cutoff, sizeof(double), 1, fp, nullptr, error);
      MPI_Bcast(&cutoff, 1, MPI_DOUBLE, 0, world);
      cutoff_given[index(i, j)] = cutoff_given[index(j, i)] = cutoff;
    }
}

// Every per-type, per-atom and per-pair array of the style (the history is its fix's).
double PairLubricatedSpringDashpot::memory_usage()
{
  const double ints = candidate_i.capacity() + candidate_j.capacity() + candidate_jj.capacity() + film_i.capacity() +
                      film_j.capacity() + group_count.capacity() + group_keys.capacity() + record_i.capacity() +
                      record_j.capacity() + network_i.capacity() + network_j.capacity();
  const double doubles = maxrad.capacity() + max_reach.capacity() + network_load.capacity() + network_bound.capacity() +
                         step_reach.capacity() + inverse_mass.capacity() + load_of_atom.capacity() +
                         scale_of_atom.capacity() + record_force.capacity() + record_shear.capacity() +
                         network_sums.capacity();
  return Pair::memory_usage() + coeffs.capacity() * sizeof(lub::Coefficients) +
         models.capacity() * sizeof(lub::ContactModel) + ints * sizeof(int) + doubles * sizeof(double);
}

// write_data: the pair_coeff words of each type pair (Pair Coeffs: i i; PairIJ Coeffs: i <= j),
// which read_data gives back to coeff() (lubricated::coefficients_words, and cutoff if given).
std::string PairLubricatedSpringDashpot::pair_coeff_words(int i, int j) const
{
  std::string words = lub::coefficients_words(coeffs[index(i, j)]);
  if (cutoff_given[index(i, j)] > 0.0) {
    char cutoff[40];
    std::snprintf(cutoff, sizeof cutoff, " cutoff %.17g", cutoff_given[index(i, j)]);
    words += cutoff;
  }
  return words;
}

void PairLubricatedSpringDashpot::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fprintf(fp, "%d %s\n", i, pair_coeff_words(i, i).c_str());
}

void PairLubricatedSpringDashpot::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      fprintf(fp, "%d %d %s\n", i, j, pair_coeff_words(i, j).c_str());
}
