/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot (see doc/pair_lubricated_springdashpot.rst)
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"
#include "vector_pairs.h"

#include "fix_contact_history/fix_contact_history.h"
#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_wall_lubrication/fix_wall_lubrication.h"
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
  finitecutflag = 1;
  restartinfo = 1;
  // The film budget: scales forward, loads reverse (1 value per atom); the contact masses
  // forward (1); the contact-network check: its sums both ways (lub::network_values).
  comm_forward = comm_reverse = lub::network_values;
}

PairLubricatedSpringDashpot::~PairLubricatedSpringDashpot()
{
  delete[] svector;
  // The history fix goes with the pair style (modify outlives force at shutdown).
  if (history && modify->get_fix_by_id(history_id)) modify->delete_fix(history_id);
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
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  coeffs.assign((n + 1) * (n + 1), lub::Coefficients());
  models.assign((n + 1) * (n + 1), lub::NormalModel());
  tmodels.assign((n + 1) * (n + 1), lub::TangentialModel());
  max_reach.assign((n + 1) * (n + 1), 0.0);
  network_load.assign((n + 1) * (n + 1), 0.0);
  network_bound.assign((n + 1) * (n + 1), 0.0);
  maxrad.assign(n + 1, 0.0);
}

// pair_style lubricated/springdashpot [vector yes|no] [limit atom|pair]
void PairLubricatedSpringDashpot::settings(int narg, char **arg)
{
  vector_enabled = true;
  limit_per_atom = true;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (key != "vector" && key != "limit")
      error->all(FLERR, "{}: unknown keyword '{}' (allowed: vector yes|no, limit atom|pair; "
                 "coefficients go in pair_coeff)", STYLE, key);
    const char *allowed = key == "vector" ? "yes or no" : "atom or pair";
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value ({})", STYLE, key, allowed);
    const std::string value = arg[iarg + 1];
    if (key == "vector") {
      if (value != "yes" && value != "no")
        error->all(FLERR, "{}: vector = {} is not allowed (yes or no)", STYLE, value);
      vector_enabled = value == "yes";
    } else {
      if (value != "atom" && value != "pair")
        error->all(FLERR, "{}: limit = {} is not allowed (atom or pair)", STYLE, value);
      limit_per_atom = value == "atom";
    }
  }
}

// One int: bit 0 vector no, bit 1 limit pair (files written before `limit` read as atom).
void PairLubricatedSpringDashpot::write_restart_settings(FILE *fp)
{
  const int flag = (vector_enabled ? 1 : 0) | (limit_per_atom ? 0 : 2);
  fwrite(&flag, sizeof(int), 1, fp);
}

void PairLubricatedSpringDashpot::read_restart_settings(FILE *fp)
{
  int flag = 1;
  if (comm->me == 0) utils::sfread(FLERR, &flag, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&flag, 1, MPI_INT, 0, world);
  vector_enabled = (flag & 1) != 0;
  limit_per_atom = (flag & 2) == 0;
}

// pair_coeff I J e_d [ncontact N | tcontact t_c] [viscosity mu_f] [activation eps_al | grid dx]
//                    [saturation eps_1] [release eps_2]
void PairLubricatedSpringDashpot::coeff(int narg, char **arg)
{
  if (narg < 3) error->all(FLERR, "{}: pair_coeff needs I J e_d [keyword value ...]", STYLE);
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  std::vector<std::string> words(arg + 2, arg + narg);
  lub::Coefficients c;
  const std::string problem = lub::parse_coefficients(words, 0, c);
  if (!problem.empty()) error->all(FLERR, "{} pair_coeff {} {}: {}", STYLE, arg[0], arg[1], problem);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      coeffs[index(i, j)] = c;
      coeffs[index(j, i)] = c;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "{}: incorrect atom types in pair_coeff {} {}", STYLE, arg[0], arg[1]);
}

void PairLubricatedSpringDashpot::init_style()
{
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
      const lub::Coefficients &c = coeffs[index(i, j)];
      const std::string problem = lub::validate_time_step(c, update->dt);
      if (!problem.empty()) error->all(FLERR, "{} types {} {}: {}", STYLE, i, j, problem);
      advice.insert(lub::time_step_warning(c, update->dt));
      advice.insert(lub::calibration_warning(c, lub::Partner::particle));
      any_wet = any_wet || c.wet();
      any_tangential = any_tangential || c.tangential();
      any_friction = any_friction || c.friction > 0.0;
      any_shear_film = any_shear_film || (c.wet() && c.shear_film());
    }
  if (any_tangential && !(atom->omega_flag && atom->torque_flag))
    error->all(FLERR, "{} with friction, rolling or shearfilm requires per-atom omega and torque "
               "(atom_style sphere)", STYLE);
  // Friction needs the tangential elongation of every contact, kept by a fix of our own
  // that follows atoms across neighbor-list rebuilds, ranks and restart files.
  if (any_friction && !history) {
    history_id = "LUBRICATED_HISTORY_" + std::to_string(instance_me);
    history = dynamic_cast<FixContactHistory *>(
        modify->add_fix(history_id + " all LUBRICATED_HISTORY 3"));
    if (!history) error->all(FLERR, "{}: could not create its contact-history fix", STYLE);
  }
  if (!any_friction && history) {
    modify->delete_fix(history_id);
    history = nullptr;
  }
  if (comm->me == 0)
    for (const auto &msg : advice)
      if (!msg.empty()) error->warning(FLERR, "{}: {}", STYLE, msg);

  // Under fix nve/sphere/midpoint forces are evaluated with the extrapolated V~; the step-exact
  // integration needs the velocity over the last step instead, which that fix provides.
  midpoint = nullptr;
  for (auto &ifix : modify->get_fix_by_style("^nve/sphere/midpoint$"))
    midpoint = dynamic_cast<FixNVESphereMidpoint *>(ifix);

  // The vectorised loops need the step velocity in v and exactly integrated normal forces;
  // type pairs with other coefficients are grouped by type pair (vector_forces).
  vector_loops = vector_enabled && !any_tangential && !midpoint;
  uniform_models = true;
  double first[lub::Coefficients::packed_size], other[lub::Coefficients::packed_size];
  coeffs[index(1, 1)].pack(first);
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j]) continue;
      coeffs[index(i, j)].pack(other);
      vector_loops = vector_loops && coeffs[index(i, j)].exact_contact;
      uniform_models = uniform_models && std::equal(first, first + lub::Coefficients::packed_size, other);
    }
  if (vector_loops && comm->me == 0)
    utils::logmesg(lmp, "{}: pairs in sustained contact{} take vectorised loops\n", STYLE,
                   any_wet ? " and pairs apart over a step" : "");

  // The many-body film budget covers the films of these pairs and of the wet walls.
  walls.clear();
  bool wet_walls = false;
  for (auto &ifix : modify->get_fix_by_style("^wall/lubrication$")) {
    auto wall = dynamic_cast<FixWallLubrication *>(ifix);
    if (!wall) continue;
    walls.push_back(wall);
    wet_walls = wet_walls || wall->wet();
  }
  film_budget = limit_per_atom && (any_wet || wet_walls);
  shear_records = film_budget && any_shear_film;    // the shear films share the budget
  if (!film_budget) scale_of_atom.clear();
  if ((any_wet || wet_walls) && comm->me == 0)
    utils::logmesg(lmp, "{}: {}\n", STYLE, film_budget ? "films within each sphere's many-body budget (limit atom)"
                                                       : "each film within its own cap only (limit pair)");

  // Immovable atoms and rigid bodies, found anew at every run (fixes and groups may change).
  contact_mass.init(STYLE, true);
  inverse_mass_on = contact_mass.active();

  // A dry model acts only in contact: a radius-based list is enough and cheapest. The film
  // acts beyond contact, where radius-based lists lose pairs on rebuild (LAMMPS PR #4685),
  // so a wet model asks for a list with per-type cutoffs that cover the whole film.
  neighbor->add_request(this, any_wet ? NeighConst::REQ_DEFAULT : NeighConst::REQ_SIZE);

  // A point particle (diameter 0) has no contact surface and no film (R = 0 in 1/eps):
  // refused at each run setup rather than evaluated as NaN.
  for (int i = 0; i < atom->nlocal; i++)
    if (!(atom->radius[i] > 0.0))
      error->one(FLERR, "{}: atom {} has diameter {} (allowed: > 0; a point particle has no contact "
                 "or film)", STYLE, atom->tag[i], 2.0 * atom->radius[i]);

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
  if (!setflag[i][j])
    error->all(FLERR, "{}: coefficients for atom types {} {} are not set (no mixing)", STYLE, i, j);
  const lub::Coefficients &c = coeffs[index(i, j)];
  models[index(i, j)] = models[index(j, i)] =
      lub::make_normal_model(c, lub::Partner::particle, update->dt);
  tmodels[index(i, j)] = tmodels[index(j, i)] = lub::make_tangential_model(c, update->dt);
  set_network_loads(i, j);
  if (comm->me == 0) {
    // Report what was derived (k and c per unit reduced mass, the contact resolution).
    const lub::NormalModel &m = models[index(i, j)];
    utils::logmesg(lmp, "{} types {} {}: e_d = {}, t_c = {:.6g} ({:.3g} steps), k/m_e = {:.6g}, "
                   "c/m_e = {:.6g}, {}{}\n", STYLE, i, j, c.e_dry, c.contact_time(update->dt),
                   c.steps_per_contact(update->dt), m.contact.stiffness_per_mass,
                   m.contact.damping_per_mass,
                   c.wet() ? fmt::format("film mu_f = {}, ", c.viscosity) : std::string("dry, "),
                   c.exact_contact ? "integration exact" : "integration sampled");
    if (c.tangential())
      utils::logmesg(lmp, "{} types {} {}: friction mu_c = {}, e_t = {}, rolling mu_r = {}, "
                     "shear film {}\n", STYLE, i, j, c.friction, c.tangential_restitution(),
                     c.rolling_friction, c.wet() && c.shear_film() ? "on" : "off");
  }

  // The film of the largest pair of these types reaches farthest.
  double reach = 0.0;
  if (c.wet() && maxrad[i] > 0.0 && maxrad[j] > 0.0)
    reach = models[index(i, j)].reach(lub::lubrication_radius_pair(maxrad[i], maxrad[j]));
  max_reach[index(i, j)] = max_reach[index(j, i)] = reach;
  return maxrad[i] + maxrad[j] + reach;
}

void PairLubricatedSpringDashpot::update_models()
{
  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++)
      if (setflag[i][j]) {
        models[index(i, j)] = models[index(j, i)] =
            lub::make_normal_model(coeffs[index(i, j)], lub::Partner::particle, update->dt);
        tmodels[index(i, j)] = tmodels[index(j, i)] =
            lub::make_tangential_model(coeffs[index(i, j)], update->dt);
        set_network_loads(i, j);
      }
}

// Load of a sustained contact of these types (contact_network.h): kappa + 2 gamma of its per-step
// constants, and the larger of it and the tangential spring's (friction) for the upper bound.
void PairLubricatedSpringDashpot::set_network_loads(int i, int j)
{
  const lub::NormalModel &m = models[index(i, j)];
  const double dt = update->dt;
  const double load = m.exact
      ? lub::contact_load(m.step.stiffness_step, m.step.damping_step, dt)
      : lub::contact_load(m.contact.stiffness_per_mass, m.contact.damping_per_mass, dt);
  const lub::TangentialModel &tm = tmodels[index(i, j)];
  const double bound =
      tm.contact_active() ? std::max(load, lub::contact_load(tm.stiffness_step, tm.damping_step, dt)) : load;
  network_load[index(i, j)] = network_load[index(j, i)] = load;
  network_bound[index(i, j)] = network_bound[index(j, i)] = bound;
  network_check = network_check || bound > lub::network_check_load;
}

// k = m_e (pi^2 + ln^2 e_d) / (N_c dt)^2 follows the time step when N_c is given.
void PairLubricatedSpringDashpot::reset_dt()
{
  update_models();
}

void PairLubricatedSpringDashpot::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (inverse_mass_on && (neighbor->ago == 0 || update->setupflag)) update_inverse_mass();
  if (!film_budget) film_budget_now = false;
  else if (neighbor->ago == 0 || update->setupflag || update->dt != film_bound_dt)
    film_budget_now = films_can_exceed_budget();
  if (film_budget_now) begin_film_budget();
  // A scene pays only for what it uses: one loop per combination.
  if (any_tangential) {
    if (any_wet) eval<true, true>();
    else eval<false, true>();
  } else {
    // The vectorised loops for steps (a run's set-up evaluates with full-step velocities).
    const bool vectorised = vector_loops && !update->setupflag;
    if (any_wet) vectorised ? eval<true, false, true>() : eval<true, false>();
    else vectorised ? eval<false, false, true>() : eval<false, false>();
  }
  if (film_budget_now) finish_film_budget();
  if (vflag_fdotr) virial_fdotr_compute();
}

// Until the next neighbor list build a pair closes by at most the skin, so only the pairs of the
// list whose gap is below the film's reach plus the skin can have a film. Each atom's sum of
// those contacts' share bounds (and its wet walls') bounds its load: where no sum exceeds 1
// the budget would scale nothing and is skipped until the next build (or a new time step).
// The bounds use the spheres' own masses, which no contact mass exceeds (contact_mass.h).
bool PairLubricatedSpringDashpot::films_can_exceed_budget()
{
  double **x = atom->x;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, newton_pair = force->newton_pair;
  const double dt = update->dt, skin = neighbor->skin;
  film_bound_dt = dt;
  if (static_cast<int>(load_of_atom.size()) < nall) {
    load_of_atom.resize(atom->nmax);
    scale_of_atom.resize(atom->nmax);
  }
  // The shear film's share has no such bound yet: with it the budget always runs.
  for (const auto &tm : tmodels)
    if (tm.film_active()) return true;
  double *bound = load_of_atom.data();
  std::fill(bound, bound + nall, 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const lub::Lubrication &film = models[index(type[i], type[j])].lubrication;
      if (!film.active()) continue;
      const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
      const lub::FilmRadius radius_ij = lub::film_radius_pair(radius[i], radius[j]);
      const double reach = radius[i] + radius[j] + film.reach(radius_ij.value) + skin;
      if (delx * delx + dely * dely + delz * delz >= reach * reach) continue;
      const double b =
          lub::film_share_bound(film, radius_ij.value, lub::reduced_mass(rmass[i], rmass[j]), dt);
      bound[i] += b;
      if (newton_pair || j < nlocal) bound[j] += b;
    }
  }
  for (auto wall : walls) wall->add_film_share_bounds(bound, nlocal);
  if (newton_pair) {
    comm_what = COMM_LOAD;
    comm->reverse_comm(this);
  }
  // A margin for the rounding of the film's integral (film_budget.h, ~1e-12 relative).
  constexpr double below_one = 1.0 - 1e-6;
  int over = 0;
  for (int i = 0; i < nlocal; i++) over |= bound[i] > below_one;
  int any_over = 0;
  MPI_Allreduce(&over, &any_over, 1, MPI_INT, MPI_MAX, world);
  return any_over != 0;
}

// Owned atoms' inverse contact masses, then the ghosts' (a rigid body's mass is known to the
// owner of the atom only). Atoms change rank and index only when the lists are rebuilt.
void PairLubricatedSpringDashpot::update_inverse_mass()
{
  if (static_cast<int>(inverse_mass.size()) < atom->nlocal + atom->nghost) inverse_mass.resize(atom->nmax);
  contact_mass.fill(inverse_mass.data());
  comm_what = COMM_MASS;
  comm->forward_comm(this);
}

// Loads start from the walls' films (computed in their pre_force) for owned atoms, 0 elsewhere.
void PairLubricatedSpringDashpot::begin_film_budget()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (static_cast<int>(load_of_atom.size()) < nall) {
    load_of_atom.resize(atom->nmax);
    scale_of_atom.resize(atom->nmax);
  }
  std::fill(load_of_atom.begin(), load_of_atom.begin() + nall, 0.0);
  for (auto wall : walls) wall->add_film_loads(load_of_atom.data(), nlocal);
  nrecord = 0;
}

void PairLubricatedSpringDashpot::reserve_records(int more)
{
  if (nrecord + more <= static_cast<int>(record_i.size()) &&
      (!shear_records || record_shear.size() >= 3 * record_i.size()))
    return;
  const int size = 2 * (nrecord + more);
  record_i.resize(size);
  record_j.resize(size);
  record_force.resize(size);
  if (shear_records) record_shear.resize(3 * size);
}

// Loads summed on the owners, scales sent to the ghosts, then every film whose atoms are over
// budget is scaled down by 1 / max(1, D_i, D_j) (lubricated/film_budget.h).
void PairLubricatedSpringDashpot::finish_film_budget()
{
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  if (newton_pair) {
    comm_what = COMM_LOAD;
    comm->reverse_comm(this);
  }
  double *load = load_of_atom.data(), *scale = scale_of_atom.data();
  // An atom no contact moves is not part of the state the budget protects: its load limits
  // nothing (its partners' own loads count their shares of these films).
  const double *held = inverse_mass_on ? inverse_mass.data() : nullptr;
  int over = 0;
  for (int i = 0; i < nlocal; i++) {
    scale[i] = (held && held[i] == 0.0) ? 1.0 : lub::film_scale_of_load(load[i]);
    over |= scale[i] < 1.0;
  }
  // Most steps of most beds leave every film whole: then no scales travel and nothing is redone.
  int any_over = 0;
  MPI_Allreduce(&over, &any_over, 1, MPI_INT, MPI_MAX, world);
  if (!any_over) return;
  comm_what = COMM_SCALE;
  comm->forward_comm(this);
  double **x = atom->x, **f = atom->f;
  if (shear_records) {
    finish_shear_film_budget();
    return;
  }
  for (int r = 0; r < nrecord; r++) {
    const int i = record_i[r], j = record_j[r];
    const double s = std::min(scale[i], scale[j]);
    if (s == 1.0) continue;
    const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
    const double fpair = (s - 1.0) * record_force[r] / std::sqrt(delx * delx + dely * dely + delz * delz);
    f[i][0] += delx * fpair;
    f[i][1] += dely * fpair;
    f[i][2] += delz * fpair;
    if (newton_pair || j < nlocal) {
      f[j][0] -= delx * fpair;
      f[j][1] -= dely * fpair;
      f[j][2] -= delz * fpair;
    }
    if (evflag) ev_tally(i, j, nlocal, newton_pair, 0.0, 0.0, fpair, delx, dely, delz);
  }
}

// The correction pass with shear films: per record, (s - 1) times the normal film along n and the
// shear film at the contact points, with its torques -R_i n x f and -R_j n x f (tangential.h).
void PairLubricatedSpringDashpot::finish_shear_film_budget()
{
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double *scale = scale_of_atom.data(), *radius = atom->radius;
  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  for (int r = 0; r < nrecord; r++) {
    const int i = record_i[r], j = record_j[r];
    const double s = std::min(scale[i], scale[j]);
    if (s == 1.0) continue;
    const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
    const double rinv = 1.0 / std::sqrt(delx * delx + dely * dely + delz * delz);
    const double fpair = (s - 1.0) * record_force[r] * rinv;
    const double *shear = &record_shear[3 * r];
    const lub::Vec3 df{(s - 1.0) * shear[0], (s - 1.0) * shear[1], (s - 1.0) * shear[2]};
    const lub::Vec3 nxf = lub::cross(lub::Vec3{delx * rinv, dely * rinv, delz * rinv}, df);
    const double fx = delx * fpair + df.x, fy = dely * fpair + df.y, fz = delz * fpair + df.z;
    const double radi = radius[i], radj = radius[j];
    f[i][0] += fx;
    f[i][1] += fy;
    f[i][2] += fz;
    torque[i][0] -= radi * nxf.x;
    torque[i][1] -= radi * nxf.y;
    torque[i][2] -= radi * nxf.z;
    if (newton_pair || j < nlocal) {
      f[j][0] -= fx;
      f[j][1] -= fy;
      f[j][2] -= fz;
      torque[j][0] -= radj * nxf.x;
      torque[j][1] -= radj * nxf.y;
      torque[j][2] -= radj * nxf.z;
    }
    if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
  }
}

int PairLubricatedSpringDashpot::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/,
                                                   int * /*pbc*/)
{
  if (comm_what == COMM_NETWORK) {
    constexpr int nv = lub::network_values;
    for (int k = 0; k < n; k++) std::copy_n(&network_sums[nv * list[k]], nv, buf + nv * k);
    return nv * n;
  }
  const double *values = comm_what == COMM_MASS ? inverse_mass.data() : scale_of_atom.data();
  for (int k = 0; k < n; k++) buf[k] = values[list[k]];
  return n;
}

void PairLubricatedSpringDashpot::unpack_forward_comm(int n, int first, double *buf)
{
  if (comm_what == COMM_NETWORK) {
    std::copy_n(buf, lub::network_values * n, &network_sums[lub::network_values * first]);
    return;
  }
  double *values = comm_what == COMM_MASS ? inverse_mass.data() : scale_of_atom.data();
  for (int k = 0; k < n; k++) values[first + k] = buf[k];
}

int PairLubricatedSpringDashpot::pack_reverse_comm(int n, int first, double *buf)
{
  if (comm_what == COMM_NETWORK) {
    std::copy_n(&network_sums[lub::network_values * first], lub::network_values * n, buf);
    return lub::network_values * n;
  }
  for (int k = 0; k < n; k++) buf[k] = load_of_atom[first + k];
  return n;
}

void PairLubricatedSpringDashpot::unpack_reverse_comm(int n, int *list, double *buf)
{
  if (comm_what == COMM_NETWORK) {
    constexpr int nv = lub::network_values;
    for (int k = 0; k < n; k++)
      for (int q = 0; q < nv; q++) network_sums[nv * list[k] + q] += buf[nv * k + q];
    return;
  }
  for (int k = 0; k < n; k++) load_of_atom[list[k]] += buf[k];
}

// The network of contacts (lubricated/contact_network.h): per-atom sums over the contacts in
// overlap now and a step ago among the pairs pass 1 kept, then each contact's lower quotient and
// upper row. A lower quotient of 4 or more proves a mode that grows every step: ERROR. Where the
// upper row reaches 4 (stability unproven) and the lower quotient 8/3 (growth likely): WARNING,
// once per run.
void PairLubricatedSpringDashpot::check_contact_network(int ncandidate)
{
  constexpr int nv = lub::network_values;
  double **x = atom->x, **v = atom->v;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, newton_pair = force->newton_pair;
  const double dt = update->dt;
  if (static_cast<int>(network_sums.size()) < nv * nall) network_sums.resize(nv * atom->nmax);
  std::fill(network_sums.begin(), network_sums.begin() + nv * nall, 0.0);
  network_i.clear();
  network_j.clear();
  auto normal = [&](int i, int j, double *n) {
    for (int d = 0; d < 3; d++) n[d] = x[i][d] - x[j][d];
    return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  };
  // The masses the contacts move (contact_mass.h): an immovable atom is not part of the state,
  // its infinite mass drops its terms from the sums and quotients.
  const double *inverse = inverse_mass_on ? inverse_mass.data() : nullptr;
  auto mass = [&](int i) { return inverse ? (inverse[i] > 0.0 ? 1.0 / inverse[i] : INFINITY) : rmass[i]; };
  auto pair_mass = [&](int i, int j) {
    return inverse ? lub::reduced_mass_of_inverses(inverse[i], inverse[j]) : lub::reduced_mass(rmass[i], rmass[j]);
  };
  for (int c = 0; c < ncandidate; c++) {
    const int i = candidate_i[c], j = candidate_j[c];
    double n[3];
    const double r = normal(i, j, n), gap = r - radius[i] - radius[j];
    if (!(gap < 0.0) || r == 0.0) continue;
    const double *vi = midpoint ? midpoint->step_velocity(i) : v[i];
    const double *vj = midpoint ? midpoint->step_velocity(j) : v[j];
    for (int d = 0; d < 3; d++) n[d] /= r;
    const double u_n = (vi[0] - vj[0]) * n[0] + (vi[1] - vj[1]) * n[1] + (vi[2] - vj[2]) * n[2];
    if (!(gap - u_n * dt < 0.0)) continue;    // in overlap a step ago too
    const int t = index(type[i], type[j]);
    const double m_e = pair_mass(i, j);
    if (m_e == 0.0) continue;    // two immovable atoms
    lub::add_network_contact(&network_sums[nv * i], network_load[t], network_bound[t], m_e, n);
    if (newton_pair || j < nlocal)
      lub::add_network_contact(&network_sums[nv * j], network_load[t], network_bound[t], m_e, n);
    network_i.push_back(i);
    network_j.push_back(j);
  }
  comm_what = COMM_NETWORK;
  if (newton_pair) comm->reverse_comm(this);
  comm->forward_comm(this);

  // Each contact's bounds; the worst over all ranks decides (contact_network_ranks.h).
  lub::NetworkScores scores(comm->me);
  for (std::size_t k = 0; k < network_i.size(); k++) {
    const int i = network_i[k], j = network_j[k], t = index(type[i], type[j]);
    double n[3];
    const double r = normal(i, j, n);
    for (int d = 0; d < 3; d++) n[d] /= r;
    const double m_e = pair_mass(i, j);
    const double *si = &network_sums[nv * i], *sj = &network_sums[nv * j];
    scores.add(static_cast<int>(k), lub::network_lower_quotient(network_load[t], m_e, n, si, mass(i), sj, mass(j)),
               lub::network_upper_row(network_bound[t], m_e, si, mass(i), sj, mass(j)), network_bound[t]);
  }
  lub::NetworkFinding found;
  auto describe = [&](int k, int *types, long long *tags, double *contacts) {
    const int ij[2] = {network_i[k], network_j[k]};
    for (int s = 0; s < 2; s++) {
      types[s] = type[ij[s]];
      tags[s] = static_cast<long long>(atom->tag[ij[s]]);
      contacts[s] = network_sums[nv * ij[s] + nv - 1];
    }
  };
  if (!scores.decide(world, network_warned, describe, found)) return;
  const std::string message =
      lub::network_message(STYLE, coeffs[index(found.type_i, found.type_j)], update->dt, found);
  if (found.unstable) error->all(FLERR, message);
  if (comm->me == 0) error->warning(FLERR, message);
}

// Tangential force ft on i (on j: -ft) and the torques ti, tj of one pair (tangential.h);
// dv = v_i - v_j as used for u_n.
inline void PairLubricatedSpringDashpot::tangential(int i, int j, int jj, const double *del,
                                                    const double *dv_ij, double rinv, double gap,
                                                    double u_n, double lub_radius, double m_e,
                                                    double normal_force, double *ft, double *ti,
                                                    double *tj, double kick_time, double *shear)
{
  const lub::TangentialModel &tm = tmodels[index(atom->type[i], atom->type[j])];
  const double radi = atom->radius[i], radj = atom->radius[j];
  double **omega = atom->omega;
  const lub::Vec3 n{del[0] * rinv, del[1] * rinv, del[2] * rinv};
  const lub::Vec3 dv{dv_ij[0], dv_ij[1], dv_ij[2]};
  const lub::Vec3 wi{omega[i][0], omega[i][1], omega[i][2]};
  const lub::Vec3 wj{omega[j][0], omega[j][1], omega[j][2]};
  const lub::Vec3 s =
      lub::tangential_part(lub::minus(dv, lub::cross(lub::plus(lub::scaled(wi, radi),
                                                               lub::scaled(wj, radj)), n)), n);
  const double m_t = lub::tangential_mass_ratio * m_e;

  lub::Vec3 f;
  if (history) {
    char &touched = history->touched(i)[jj];
    double *h = history->values(i) + 3 * jj;
    if (tm.contact_active() && lub::tangential_in_contact(gap)) {
      const double fraction = touched ? 1.0 : lub::first_contact_fraction(gap, u_n, tm.dt);
      lub::Vec3 delta{h[0], h[1], h[2]};
      f = lub::tangential_contact_force(tm, delta, n, s, m_t, normal_force, fraction);
      h[0] = delta.x, h[1] = delta.y, h[2] = delta.z;
      touched = 1;
    } else if (touched) {
      touched = 0;
      h[0] = h[1] = h[2] = 0.0;
    }
  }
  if (tm.film_active()) {
    const lub::Lubrication &film = models[index(atom->type[i], atom->type[j])].lubrication;
    const double eps = gap / lub_radius;
    const lub::Vec3 fs = lub::shear_film_force(tm, s, eps, film.activation_for(lub_radius),
                                               film.eps_saturation, film.eps_release,
                                               radi * radj / (radi + radj), m_t);
    f = lub::plus(f, fs);
    if (shear) {
      shear[0] = fs.x, shear[1] = fs.y, shear[2] = fs.z;
      shear[3] = lub::shear_film_share(lub::dot(fs, fs), lub::dot(s, s), m_t, kick_time);
    }
  }
  lub::Vec3 roll;
  if (tm.rolling_active() && gap < 0.0) {
    // The spheres' own inertia (also in a rigid body); against an immovable atom the other's.
    const double inertia_i = 0.4 * atom->rmass[i] * radi * radi;
    const double inertia_j = 0.4 * atom->rmass[j] * radj * radj;
    double inertia = inertia_i * inertia_j / (inertia_i + inertia_j);
    if (inverse_mass_on && inverse_mass[i] == 0.0) inertia = inertia_j;
    if (inverse_mass_on && inverse_mass[j] == 0.0) inertia = inertia_i;
    roll = lub::rolling_torque(tm, n, lub::minus(wi, wj), radi * radj / (radi + radj), inertia, normal_force);
  }
  const lub::Vec3 nxf = lub::cross(n, f);
  ft[0] = f.x, ft[1] = f.y, ft[2] = f.z;
  ti[0] = -radi * nxf.x + roll.x, ti[1] = -radi * nxf.y + roll.y, ti[2] = -radi * nxf.z + roll.z;
  tj[0] = -radj * nxf.x - roll.x, tj[1] = -radj * nxf.y - roll.y, tj[2] = -radj * nxf.z - roll.z;
}

// A pair outside distance `outer` (squared: outer_sq) comes within it during the coming step
// at most if gap < reach + |u_n| dt, i.e. rsq - |dv.del| dt < outer r, tested without a sqrt.
static inline bool within_a_step(double rsq, double dv_dot_del, double dt, double outer_sq)
{
  const double s = rsq - std::fabs(dv_dot_del) * dt;
  return (s <= 0.0) | (s * s < outer_sq * rsq);
}

// The vectorised loops (vector_pairs.h) over the film-only list and the kept entries, in
// chunks that stay in the cache between computing and applying the forces; kept entries
// where a contact starts or ends go through the general loop, evaluate(i, j, jj). Unless one
// model serves every pair, each chunk is first grouped by type pair (a counting sort).
template <class Evaluate>
void PairLubricatedSpringDashpot::vector_forces(int ncandidate, int nfilm, Evaluate &evaluate)
{
  if (ncandidate + nfilm == 0) return;
  double **x = atom->x, **f = atom->f;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const vector_pairs::Atoms atoms{x[0], atom->v[0], atom->radius, atom->rmass,
                                  inverse_mass_on ? inverse_mass.data() : nullptr};
  constexpr int chunk = 256;
  double fpair[chunk], energy[chunk], film[chunk], capacity[chunk];
  int done[chunk], rest[chunk];
  const bool budget = film_budget_now;
  auto apply = [&](int i, int j, double fij, double eij) {
    const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
    f[i][0] += delx * fij;
    f[i][1] += dely * fij;
    f[i][2] += delz * fij;
    if (newton_pair || j < nlocal) {
      f[j][0] -= delx * fij;
      f[j][1] -= dely * fij;
      f[j][2] -= delz * fij;
    }
    if (evflag) ev_tally(i, j, nlocal, newton_pair, eij, 0.0, fij, delx, dely, delz);
  };
  // The loops' films enter the budget (their kick is a step: the loops run in steps only): the
  // shares in a loop of their own (vectorised), the rest with the forces' scatter.
  const double dt = update->dt;
  auto record_films = [&](const int *pair_i, const int *pair_j, int n) {
    for (int c = 0; c < n; c++) capacity[c] = lub::film_share_of_capacity(film[c], capacity[c], dt);
    for (int c = 0; c < n; c++) record_film(pair_i[c], pair_j[c], film[c], capacity[c], nlocal, newton_pair);
  };
  // At most one chunk of pairs of one model.
  auto film_pairs = [&](const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n) {
    if (atoms.inverse_mass) vector_pairs::film_only_by_inverse(atoms, model, pair_i, pair_j, n, fpair, film, capacity);
    else vector_pairs::film_only(atoms, model, pair_i, pair_j, n, fpair, film, capacity);
    for (int c = 0; c < n; c++) apply(pair_i[c], pair_j[c], fpair[c], 0.0);
    if (budget) record_films(pair_i, pair_j, n);
  };
  auto kept_pairs = [&](const lub::NormalModel &model, const int *pair_i, const int *pair_j, int n) {
    if (atoms.inverse_mass)
      vector_pairs::contact_or_film_by_inverse(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
    else
      vector_pairs::contact_or_film(atoms, model, pair_i, pair_j, n, fpair, film, capacity, energy, done);
    int nrest = 0;
    for (int c = 0; c < n; c++) {
      // Branch-free (which pairs are done follows no pattern): the others have fpair = 0 (and
      // no film) here and are listed for the general loop.
      apply(pair_i[c], pair_j[c], fpair[c], energy[c]);
      rest[nrest] = c;
      nrest += !done[c];
    }
    if (budget && model.lubrication.active()) record_films(pair_i, pair_j, n);
    for (int k = 0; k < nrest; k++) evaluate(pair_i[rest[k]], pair_j[rest[k]], 0);
  };
  // A list in chunks, each grouped by type pair (a counting sort within the chunk, which
  // keeps the atoms' data in the cache) unless one model serves all.
  int key[chunk], grouped_i[chunk], grouped_j[chunk];
  group_count.resize(models.size(), 0);    // all zero between chunks
  auto run_list = [&](const int *list_i, const int *list_j, int count, auto &pairs) {
    for (int start = 0; start < count; start += chunk) {
      const int n = std::min(chunk, count - start);
      const int *pair_i = list_i + start, *pair_j = list_j + start;
      if (uniform_models) {
        pairs(models[index(1, 1)], pair_i, pair_j, n);
        continue;
      }
      group_keys.clear();
      for (int c = 0; c < n; c++) {
        key[c] = index(type[pair_i[c]], type[pair_j[c]]);
        if (group_count[key[c]]++ == 0) group_keys.push_back(key[c]);
      }
      int begin = 0;
      for (int k : group_keys) {    // group_count becomes each group's next free slot
        const int size = group_count[k];
        group_count[k] = begin;
        begin += size;
      }
      for (int c = 0; c < n; c++) {
        const int at = group_count[key[c]]++;
        grouped_i[at] = pair_i[c];
        grouped_j[at] = pair_j[c];
      }
      begin = 0;
      for (int k : group_keys) {
        pairs(models[k], grouped_i + begin, grouped_j + begin, group_count[k] - begin);
        begin = group_count[k];
        group_count[k] = 0;
      }
    }
  };
  run_list(film_i.data(), film_j.data(), nfilm, film_pairs);
  run_list(candidate_i.data(), candidate_j.data(), ncandidate, kept_pairs);
}

template <bool WET, bool TANGENTIAL, bool SPLIT> void PairLubricatedSpringDashpot::eval()
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const double *radius = atom->radius;
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double dt = update->dt;
  // Full-step velocities at a run start, used by each integrator its own way (contact_step.h).
  const lub::Evaluation when = lub::evaluation_of(update->setupflag != 0, midpoint != nullptr);
  const double *inverse = inverse_mass_on ? inverse_mass.data() : nullptr;

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  const lub::NormalModel *model_table = models.data();
  const double *reach_table = max_reach.data();
  const int stride = ntypes_alloc + 1;

  // How far each owned or ghost atom can move in the coming step (|v|_1 dt >= |v| dt): the
  // pairs that can close their gap within it are within the sum of both.
  const int nall = atom->nlocal + atom->nghost;
  if (static_cast<int>(step_reach.size()) < nall) step_reach.resize(atom->nmax);
  for (int k = 0; k < nall; k++) {
    const double *vk = midpoint ? midpoint->step_velocity(k) : v[k];
    step_reach[k] = (std::fabs(vk[0]) + std::fabs(vk[1]) + std::fabs(vk[2])) * dt;
  }
  const double *moves = step_reach.data();

  // Pass 1, branch-free: keep the list entries that can act within the coming step: in the
  // film's reach (the largest of the two types) or in contact, or within what both atoms
  // can move in a step. With friction, entries holding an elongation to forget are kept too.
  // Whether an entry is kept follows no pattern a branch predictor could learn, hence no branch.
  // SPLIT: entries apart by more than both atoms can move in the step (no contact can start)
  // but in the film's reach go to the film-only list instead.
  int ncandidate = 0, nfilm = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const double radi_moved = radius[i] + moves[i];
    const double *reach_row = reach_table + type[i] * stride;
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    const char *touched = TANGENTIAL && history ? history->touched(i) : nullptr;
    if (ncandidate + jnum > static_cast<int>(candidate_i.size())) {
      candidate_i.resize(2 * (ncandidate + jnum));
      candidate_j.resize(2 * (ncandidate + jnum));
      if (TANGENTIAL) candidate_jj.resize(2 * (ncandidate + jnum));
    }
    if (WET && SPLIT && nfilm + jnum > static_cast<int>(film_i.size())) {
      film_i.resize(2 * (nfilm + jnum));
      film_j.resize(2 * (nfilm + jnum));
    }
    int *out_i = candidate_i.data(), *out_j = candidate_j.data(), *out_jj = candidate_jj.data();
    int *film_out_i = film_i.data(), *film_out_j = film_j.data();
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xi - x[j][0];
      const double dely = yi - x[j][1];
      const double delz = zi - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double touch = radi_moved + radius[j] + moves[j];
      const double near = touch + (WET ? reach_row[type[j]] : 0.0);
      out_i[ncandidate] = i;
      out_j[ncandidate] = j;
      if (TANGENTIAL) out_jj[ncandidate] = jj;
      int keep = rsq < (SPLIT ? touch * touch : near * near);
      if (WET && SPLIT) {
        film_out_i[nfilm] = i;
        film_out_j[nfilm] = j;
        nfilm += (rsq < near * near) & !keep;
      }
      if (TANGENTIAL && touched) keep |= touched[jj];
      ncandidate += keep;
    }
  }

  if (network_check && !update->setupflag && update->ntimestep >= network_next) {
    network_next = update->ntimestep + lub::network_check_interval;
    check_contact_network(ncandidate);
  }

  // Pass 2: the pairs kept by pass 1 (j kept with them: no second look-up in the neighbor
  // list; jj for the history only).
  double **torque = atom->torque;
  const bool budget = WET && film_budget_now;
  if (budget) reserve_records(ncandidate + nfilm);
  const double kick_time = lub::film_kick_time(dt, when != lub::Evaluation::step,
                                               when == lub::Evaluation::midpoint_start);
  auto evaluate = [&](const int i, const int j, const int jj) __attribute__((always_inline)) {
    const double delx = x[i][0] - x[j][0];
    const double dely = x[i][1] - x[j][1];
    const double delz = x[i][2] - x[j][2];
    const double rsq = delx * delx + dely * dely + delz * delz;
    const double radi = radius[i];
    const double radsum = radi + radius[j];
    const lub::NormalModel &model = model_table[type[i] * stride + type[j]];
    // A pair that is not in contact now has no elongation to keep.
    auto forget = [&]() {
      if (TANGENTIAL && history) {
        char &touched = history->touched(i)[jj];
        if (touched) {
          touched = 0;
          double *h = history->values(i) + 3 * jj;
          h[0] = h[1] = h[2] = 0.0;
        }
      }
    };

    const double *vi = v[i], *vj = v[j];
    if (midpoint && model.exact) vi = midpoint->step_velocity(i), vj = midpoint->step_velocity(j);
    const double dvx = vi[0] - vj[0];
    const double dvy = vi[1] - vj[1];
    const double dvz = vi[2] - vj[2];

    lub::FilmRadius film;
    double reach = 0.0;
    if (WET && model.lubrication.active()) {
      film = lub::film_radius_pair(radi, radius[j]);
      reach = model.reach(film.value);
    }
    const double outer = radsum + reach;
    if (rsq >= outer * outer) {
      // Apart and out of this pair's film (pass 1 used the types' largest): only a contact
      // starting, or a film entered or left, within a step can act.
      forget();
      if (!model.exact) return;
      if (!within_a_step(rsq, dvx * delx + dvy * dely + dvz * delz, dt, outer * outer)) return;
    }
    if (rsq == 0.0) {    // coincident centres: no normal direction is defined
      forget();
      return;
    }

    const double r = std::sqrt(rsq);
    const double rinv = 1.0 / r;
    const double u_n = (dvx * delx + dvy * dely + dvz * delz) * rinv;
    const double m_e = inverse ? lub::reduced_mass_of_inverses(inverse[i], inverse[j])
                               : lub::reduced_mass(rmass[i], rmass[j]);
    if (m_e == 0.0) {    // neither atom can move (the vectorised loops give such pairs 0)
      forget();
      return;
    }
    const lub::NormalForce fn = lub::normal_force(model, r - radsum, film, m_e, u_n, when);

    const double fpair = fn.total() * rinv;
    double fx = delx * fpair, fy = dely * fpair, fz = delz * fpair;
    const double share = budget ? lub::film_share(fn.lubrication, m_e, u_n, kick_time) : 0.0;
    if (budget && !(TANGENTIAL && shear_records)) record_film(i, j, fn.lubrication, share, nlocal, newton_pair);
    if (TANGENTIAL) {
      double ft[3] = {0.0, 0.0, 0.0}, ti[3] = {0.0, 0.0, 0.0}, tj[3] = {0.0, 0.0, 0.0};
      // The slip uses the engine's velocities (under the midpoint integrator: V~, not the
      // step velocity of the normal contact).
      const double del[3] = {delx, dely, delz};
      double dv[3] = {dvx, dvy, dvz};
      if (vi != v[i])
        for (int d = 0; d < 3; d++) dv[d] = v[i][d] - v[j][d];
      double shear[4] = {0.0, 0.0, 0.0, 0.0};    // the shear film's force on i and share
      const bool shear_budget = budget && shear_records;
      tangential(i, j, jj, del, dv, rinv, r - radsum, u_n, film.value, m_e, fn.contact, ft, ti, tj,
                 kick_time, shear_budget ? shear : nullptr);
      if (shear_budget)
        record_films(i, j, fn.lubrication, shear, lub::contact_film_share(share, shear[3]), nlocal, newton_pair);
      fx += ft[0], fy += ft[1], fz += ft[2];
      for (int d = 0; d < 3; d++) torque[i][d] += ti[d];
      if (newton_pair || j < nlocal)
        for (int d = 0; d < 3; d++) torque[j][d] += tj[d];
    }
    f[i][0] += fx;
    f[i][1] += fy;
    f[i][2] += fz;
    if (newton_pair || j < nlocal) {
      f[j][0] -= fx;
      f[j][1] -= fy;
      f[j][2] -= fz;
    }
    if (evflag) {
      if (TANGENTIAL)
        ev_tally_xyz(i, j, nlocal, newton_pair, fn.energy, 0.0, fx, fy, fz, delx, dely, delz);
      else
        ev_tally(i, j, nlocal, newton_pair, fn.energy, 0.0, fpair, delx, dely, delz);
    }
  };

  if (SPLIT) {
    vector_forces(ncandidate, nfilm, evaluate);
    return;
  }
  for (int c = 0; c < ncandidate; c++)
    evaluate(candidate_i[c], candidate_j[c], TANGENTIAL ? candidate_jj[c] : 0);
}

double PairLubricatedSpringDashpot::single(int i, int j, int itype, int jtype, double rsq,
                                           double /*factor_coul*/, double /*factor_lj*/,
                                           double &fforce)
{
  fforce = 0.0;
  svector[0] = svector[1] = 0.0;
  const double radi = atom->radius[i], radj = atom->radius[j];
  const double radsum = radi + radj;
  const double r = std::sqrt(rsq);
  const double lub_radius = lub::lubrication_radius_pair(radi, radj);
  svector[2] = (r - radsum) / lub_radius;
  const lub::NormalModel &model = models[index(itype, jtype)];
  if (rsq == 0.0) return 0.0;

  double **x = atom->x, **v = atom->v;
  double u_n = 0.0;
  for (int d = 0; d < 3; d++) u_n += (v[i][d] - v[j][d]) * (x[i][d] - x[j][d]);
  u_n /= r;
  if (!model.acts(r - radsum, lub_radius, u_n)) return 0.0;
  const double m_e = inverse_mass_on ? lub::reduced_mass_of_inverses(inverse_mass[i], inverse_mass[j])
                                     : lub::reduced_mass(atom->rmass[i], atom->rmass[j]);
  if (m_e == 0.0) return 0.0;
  const lub::NormalForce fn = lub::normal_force(model, r - radsum, lub_radius, m_e, u_n);
  fforce = fn.total() / r;
  svector[0] = fn.contact;
  svector[1] = fn.lubrication;
  return fn.energy;
}

void PairLubricatedSpringDashpot::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  double buf[lub::Coefficients::packed_size];
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      coeffs[index(i, j)].pack(buf);
      fwrite(buf, sizeof(double), lub::Coefficients::packed_size, fp);
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
      if (me == 0)
        utils::sfread(FLERR, buf, sizeof(double), lub::Coefficients::packed_size, fp, nullptr,
                      error);
      MPI_Bcast(buf, lub::Coefficients::packed_size, MPI_DOUBLE, 0, world);
      coeffs[index(i, j)].unpack(buf);
      coeffs[index(j, i)].unpack(buf);
    }
}

double PairLubricatedSpringDashpot::memory_usage()
{
  return Pair::memory_usage() + coeffs.size() * sizeof(lub::Coefficients) +
      models.size() * sizeof(lub::NormalModel) +
      (candidate_i.capacity() + candidate_j.capacity() + candidate_jj.capacity() +
       film_i.capacity() + film_j.capacity() + group_count.capacity() + group_keys.capacity() +
       record_i.capacity() + record_j.capacity()) *
          sizeof(int) +
      (step_reach.capacity() + inverse_mass.capacity() + load_of_atom.capacity() + scale_of_atom.capacity() +
       record_force.capacity() + record_shear.capacity()) *
          sizeof(double);
}
