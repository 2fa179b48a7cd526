/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot: a run's initialisation (init_style in its steps,
   init_one) and the per type pair models
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"

#include "unit_style/unit_style.h"

#include "fix_contact_history/fix_contact_history.h"
#include "fix_nve_sphere_midpoint/fix_nve_sphere_midpoint.h"
#include "fix_step_velocity/fix_step_velocity.h"
#include "lubricated/check_setup.h"
#include "lubricated/overlap_check.h"
#include "plugin/run_steps.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <set>
#include <string>

using namespace LAMMPS_NS;
namespace lub = lubricated;

static constexpr const char *STYLE = "Pair style lubricated/springdashpot";

void PairLubricatedSpringDashpot::init_style()
{
  check_atom_style();
  network.start_run();    // set_loads (init_one) turns it on
  const TypePairNeeds needs = settle_coefficients();
  overlap_warned = overlap_deep_warned = false, overlap_depth = lub::overlap_warning_fraction;
  keep_contact_history(needs.friction);
  if (comm->me == 0)
    for (const auto &msg : needs.advice)
      if (!msg.empty()) error->warning(FLERR, "{}: {}", STYLE, msg);
  warn_hybrid_instances();
  find_integrators();
  choose_loops();
  init_film_budget(needs.shear_film);
  // Immovable atoms and rigid bodies, found anew at every run (fixes and groups may change).
  contact_mass.init(STYLE, true);
  inverse_mass_on = contact_mass.active();
  // A dry model acts only in contact: a radius-based list is enough and cheapest. The film
  // acts beyond contact, where radius-based lists lose pairs on rebuild (LAMMPS PR #4685),
  // so a wet model asks for a list with per-type cutoffs that cover the whole film.
  neighbor->add_request(this, any_wet ? NeighConst::REQ_DEFAULT : NeighConst::REQ_SIZE);
  check_grid_spacing();
  find_largest_radii();
}

void PairLubricatedSpringDashpot::check_atom_style()
{
  require_supported_units(lmp, STYLE);
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "{} requires atom_style sphere (per-atom radius and rmass)", STYLE);
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "{} requires ghost atoms to store velocity: use comm_modify vel yes", STYLE);
}

// t_c settled at the first run, each type pair's set-up checked, and what the type pairs need.
PairLubricatedSpringDashpot::TypePairNeeds PairLubricatedSpringDashpot::settle_coefficients()
{
  const int n = atom->ntypes;
  any_wet = any_tangential = false;
  TypePairNeeds needs;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j]) continue;
      lub::settle_contact_time(coeffs[index(i, j)], update->dt, run_has_steps(update));
      coeffs[index(j, i)] = coeffs[index(i, j)];
      const lub::Coefficients &c = coeffs[index(i, j)];
      const lub::SetupCheck check = lub::check_setup(c, lub::Partner::particle, update->dt);
      if (!check.error.empty()) error->all(FLERR, "{} types {} {}: {}", STYLE, i, j, check.error);
      needs.advice.insert(check.warnings.begin(), check.warnings.end());
      any_wet = any_wet || c.wet();
      any_tangential = any_tangential || c.tangential();
      needs.friction = needs.friction || c.friction > 0.0;
      needs.shear_film = needs.shear_film || (c.wet() && c.shear_film());
      needs.roll_film = needs.roll_film || (c.wet() && c.roll_film());
    }
  any_roll_film = needs.roll_film;
  if (any_tangential && !(atom->omega_flag && atom->torque_flag))
    error->all(FLERR,
               "{} with friction, rolling, shearfilm or rollfilm requires per-atom omega and torque "
               "(atom_style sphere)",
               STYLE);
  return needs;
}

// Friction needs the tangential elongation of every contact, kept by a fix of our own that
// follows atoms across neighbor-list rebuilds, ranks and restart files.
void PairLubricatedSpringDashpot::keep_contact_history(bool any_friction)
{
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
}

// Under pair_style hybrid each instance of the style keeps its own film budget, and fix
// wall/lubrication joins none where there are several (fix_wall_lubrication_base.cpp).
// (pair_match gives the only instance for any nsub, and each of several for its own.)
void PairLubricatedSpringDashpot::warn_hybrid_instances()
{
  if (any_wet && comm->me == 0 && utils::strmatch(force->pair_style, "^hybrid") &&
      force->pair_match("lubricated/springdashpot", 1, 1) != force->pair_match("lubricated/springdashpot", 1, 2))
    error->warning(FLERR,
                   "{}: several instances under pair_style hybrid: each keeps the many-body film "
                   "budget of its own pairs, and fix wall/lubrication joins none, so a sphere with films "
                   "of two is not held within one budget (limit atom); give every type pair to one "
                   "instance, whose pair_coeff takes coefficients per type pair",
                   STYLE);
}

void PairLubricatedSpringDashpot::find_integrators()
{
  // Under fix nve/sphere/midpoint forces are evaluated with the extrapolated V~; the step-exact
  // integration needs the velocity over the last step instead, which that fix provides.
  midpoint = FixNVESphereMidpoint::in_use(lmp, STYLE);
  // Under velocity Verlet a run's set-up continues the last run's steps where it can.
  step_velocity = midpoint ? nullptr : FixStepVelocity::find_or_create(lmp);
  verlet_velocities = step_velocity && step_velocity->integrated_by_nve_sphere();
}

// The vectorised loops need the step velocity in v and exactly integrated normal forces; type
// pairs with other coefficients are grouped by type pair (vector_forces.h).
void PairLubricatedSpringDashpot::choose_loops()
{
  const int n = atom->ntypes;
  vector_loops = vector_enabled && !any_tangential && !midpoint;
  // With friction or rolling, the pairs apart over a step feel the normal and shear films
  // alone: they take a vectorised film loop too; and the sustained frictional contacts theirs.
  // The rolling film is in the scalar loop only.
  film_loops = vector_enabled && any_tangential && !midpoint && !any_roll_film;
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
  if (comm->me != 0) return;
  if (vector_loops)
    utils::logmesg(lmp,
                   "{}: pairs in sustained contact{}, and contacts that start or end within a step (without "
                   "legendre), take vectorised loops\n",
                   STYLE, any_wet ? " or apart over a step" : "");
  if (film_loops && any_wet) utils::logmesg(lmp, "{}: pairs apart over a step take the vectorised film loop\n", STYLE);
  if (film_loops && history)
    utils::logmesg(lmp,
                   "{}: pairs in sustained frictional contact take a vectorised loop, and contacts that start or "
                   "end within a step (without legendre) another\n",
                   STYLE);
}

// The many-body film budget covers the films of these pairs and of the wet walls; the shear
// and rolling films share it.
void PairLubricatedSpringDashpot::init_film_budget(bool any_shear_film)
{
  // The coupled solve takes the velocities of velocity Verlet's step (fix nve/sphere), not the
  // midpoint integrator's extrapolated ones.
  if (film_solve.on && midpoint)
    error->all(FLERR,
               "{}: limit implicit is not available with fix nve/sphere/midpoint (use fix nve/sphere, "
               "or limit atom)",
               STYLE);
  budget.init(limit_per_atom, any_wet, any_shear_film, film_solve, any_roll_film);
  if ((any_wet || budget.wet_participants()) && comm->me == 0)
    utils::logmesg(lmp, "{}: {}\n", STYLE,
                   !budget.kept()  ? "each film within its own cap only (limit pair)"
                   : film_solve.on ? "films of spheres over their many-body budget solved together (limit "
                                     "implicit); the walls' films within the budget"
                                   : "films within each sphere's many-body budget (limit atom)");
}

// Point particles are refused; with a grid spacing the smallest spheres have the largest
// eps_al (at most 1, as activation).
void PairLubricatedSpringDashpot::check_grid_spacing()
{
  const int n = atom->ntypes;
  const double r_min_all = smallest_sphere_radius(lmp, STYLE, ~0);
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      const std::string problem = setflag[i][j] ? lub::validate_grid_for_radius(coeffs[index(i, j)], r_min_all) : "";
      if (!problem.empty()) error->all(FLERR, "{} types {} {}: {}", STYLE, i, j, problem);
    }
}

// Largest radius per type: atoms present now, and those fix pour/deposit may insert.
void PairLubricatedSpringDashpot::find_largest_radii()
{
  const int n = atom->ntypes;
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
  network.set_loads(i, j, models[index(i, j)]);
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
        network.set_loads(i, j, models[index(i, j)]);
      }
}

// A new time step: the per-step constants follow it; k and c stay (t_c settled at the first run,
// lubricated/coefficients.h settle_contact_time).
void PairLubricatedSpringDashpot::reset_dt()
{
  update_models();
}
