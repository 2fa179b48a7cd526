// LIGGGHTS normal model "lubricated" (normal_model_lubricated.h), what need not be inlined into
// the pair's pass: a pass's start, the close pairs' loop and the few close pairs that may touch
// (both out of line there too), and the set-up: reading and checking its properties, building its
// models, joining the film budget and bounding the films' shares at a neighbor build.
#include "liggghts/normal_model_lubricated.h"

namespace LIGGGHTS {
namespace ContactModels {

void NormalModel<LUBRICATED>::beginPass(SurfacesIntersectData &sidata, ForceData &, ForceData &)
{
  if (is_wall_) return;
  if (update->dt != dt_) build_models();
  bound_idle_pairs();
  plain_masses_ =
      hold_bits_ == 0 && (integrate_bits_ & all_group_bit) && pair_->freeze_group_bit() == 0 && !pair_->fr_pair();
  defer_close_ = defer_close_pairs(sidata);
  close_type_ = -1;
  close_.clear();
  if (!budget_) return;
  if (budget_on_ && (neighbor->ago == 0 || update->setupflag || update->dt != bound_dt_)) bound_film_shares();
  budget_->begin_pass();
}

void NormalModel<LUBRICATED>::keep_lambda_in_history(IContactHistorySetup *hsetup, int history_values)
{
  if (is_wall_ || history_values == 0 || lambda_offset_ >= 0) return;
  lambda_offset_ = hsetup->add_history_value("lubricatedEpsAl", "0");
  hsetup->add_history_value("lubricatedLambdaAl", "0");
}

void NormalModel<LUBRICATED>::apply_close_pairs()
{
  close_.apply(lmp, pair_, models_[close_type_], budget_on_ ? budget_ : nullptr);
  close_.clear();
}

void NormalModel<LUBRICATED>::close_pair_acts(SurfacesCloseData &scdata, const lubricated::NormalModel &model,
                                              ForceData &i_forces, ForceData &j_forces)
{
  const double *vi = scdata.v_i, *vj = scdata.v_j;
  const bool continued = step_velocity_->continues();
  const double r = std::sqrt(scdata.rsq), r_inverse = 1.0 / r;
  const double en[3] = {scdata.delta[0] * r_inverse, scdata.delta[1] * r_inverse, scdata.delta[2] * r_inverse};
  const double gap = r - scdata.radsum;
  double u_n = (vi[0] - vj[0]) * en[0] + (vi[1] - vj[1]) * en[1] + (vi[2] - vj[2]) * en[2];
  if (continued) u_n -= step_velocity_->kick_along(scdata.i, partner(scdata), en);
  const lubricated::FilmRadius radius = film_radius(scdata);
  if (!model.acts(gap, radius.value, u_n)) return;
  const double m_e = reduced_mass(scdata);
  lubricated::NormalForce fn;
  if (!lubricated::liggghts::film_apart(model, gap, radius, m_e, u_n, stepping(continued), fn))
    fn = lubricated::normal_force(model, gap, radius, m_e, u_n, evaluation(continued));
  if (fn.total() == 0.0) return;
  if (is_wall_ && scdata.contact_flags) *scdata.contact_flags |= CONTACT_NORMAL_MODEL;    // pairs: none apart
  apply(fn.total() * (is_wall_ ? scdata.area_ratio : 1.0), en, i_forces, j_forces);
  scdata.has_force_update = true;
  if (fn.lubrication != 0.0 && budget_on_ && budget_->active())
    record_film(scdata, fn.lubrication * (is_wall_ ? scdata.area_ratio : 1.0), en, m_e, u_n, continued);
}

void NormalModel<LUBRICATED>::bound_idle_pairs()
{
  idle_scale_ = 1.0, idle_offset_ = INFINITY;
  if (step_velocity_->continues()) return;
  const double *v = atom->v[0];
  const int nall = atom->nlocal + atom->nghost;
  double speed_max = 0.0;
  for (int k = 0; k < nall; k++)
    speed_max = std::max(speed_max, std::fabs(v[3 * k]) + std::fabs(v[3 * k + 1]) + std::fabs(v[3 * k + 2]));
  idle_scale_ = (1.0 + 0.5 * film_eps_max_) * (1.0 + 1e-9);
  idle_offset_ = (film_reach_max_ + 2.0 * speed_max * dt_) * (1.0 + 1e-9);
}

bool NormalModel<LUBRICATED>::defer_close_pairs(const SurfacesIntersectData &sidata)
{
  if (update->setupflag || !sidata.computeflag || !plain_masses_) return false;
  return !pair_->evflag && !pair_->cpl() && !pair_->storeContactForces() && !pair_->storeContactForcesStress() &&
         !pair_->store_sum_normal_force();
}
void NormalModel<LUBRICATED>::connectToProperties(PropertyRegistry &)
{
  const char *caller = is_wall_ ? "fix wall/gran model lubricated" : "pair gran model lubricated";
  ntypes_ = atom->ntypes;
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "model lubricated requires atom_style sphere (per-atom radius and rmass)");
  coefficients_ = lubricated::liggghts::read_coefficients(modify, ntypes_, caller, message_);
  if (!message_.empty()) fail(message_);
  build_models();

  // The film acts up to its reach beyond contact; the step-exact contact also needs one step
  // of approach before contact. LIGGGHTS calls surfacesClose() for gaps below
  // (factor - 1) (r_i + r_j) (pairs) or (factor - 1) r_i (walls).
  const double none = 1e300;
  double r_min = none;
  for (int i = 0; i < atom->nlocal; i++)
    r_min = std::min(r_min, atom->radius[i]);
  double r_min_all = none;
  MPI_Allreduce(&r_min, &r_min_all, 1, MPI_DOUBLE, MPI_MIN, world);
  const double reach =
      lubricated::liggghts::reach_fraction(coefficients_, ntypes_, is_wall_, r_min_all < none ? r_min_all : 0.0);
  for (const lubricated::Coefficients &c : coefficients_) {
    const std::string problem = lubricated::validate_grid_for_radius(c, r_min_all < none ? r_min_all : 0.0);
    if (!problem.empty()) fail(std::string(caller) + ": " + lubricated::liggghts::with_property_names(problem));
  }
  if (reach < 0.0)
    error->all(FLERR, "model lubricated: lubricatedGridSpacing needs the particles to exist "
                      "before the run (insert them first, or give lubricatedActivation)");
  neighbor->register_contact_dist_factor(1.0 + reach + lubricated::liggghts::approach_margin);
  warned_ = false;
  overlap_warned_ = overlap_deep_warned_ = false, overlap_depth_ = lubricated::overlap_warning_fraction;
  if (!is_wall_) find_immovable_groups();
  step_velocity_ = lubricated::liggghts::FixLubricatedStepVelocity::find_or_create(lmp);
  // With a grid spacing the factor covers the radii from r_min up: a smaller sphere inserted
  // during the run raises it before the neighbor list build where it appears.
  if (lubricated::liggghts::reach_fraction(coefficients_, ntypes_, is_wall_, 0.0) < 0.0)
    lubricated::liggghts::watch_radius(lmp, this, r_min_all,
                                       [this, caller, r_min_all](double r) { smaller_radius(r, r_min_all, caller); });
  else
    lubricated::liggghts::forget_radius(this);
  join_film_budget(caller);
  if (is_wall_) check_primitive_wall_list(caller);
  report_setup(caller);
}

void NormalModel<LUBRICATED>::report_setup(const char *caller)
{
  if (comm->me != 0) return;
  const int wall_type = is_wall_ ? static_cast<LAMMPS_NS::FixWallGran *>(hsetup_)->atom_type_wall() : 0;
  std::set<std::string> warnings;
  for (int i = 1; i <= ntypes_; i++)
    for (int j = is_wall_ ? wall_type : i; j <= (is_wall_ ? wall_type : ntypes_); j++) {
      if (j < 1 || j > ntypes_) continue;
      const lubricated::SetupCheck check =
          lubricated::check_setup(coefficients_[i * (ntypes_ + 1) + j],
                                  is_wall_ ? lubricated::Partner::wall : lubricated::Partner::particle, update->dt);
      const std::string line = std::string(caller) + " types " + std::to_string(i) + " " + std::to_string(j) + ": " +
                               check.description + "\n";
      if (screen) fputs(line.c_str(), screen);
      if (logfile) fputs(line.c_str(), logfile);
      for (const std::string &w : check.warnings)
        warnings.insert(std::string(caller) + ": " + lubricated::liggghts::with_property_names(w));
    }
  for (const std::string &w : warnings)
    error->warning(FLERR, w.c_str());
}

void NormalModel<LUBRICATED>::smaller_radius(double r, double r_start, const char *caller)
{
  for (const lubricated::Coefficients &c : coefficients_) {
    const std::string problem = lubricated::validate_grid_for_radius(c, r);
    if (!problem.empty())
      fail(std::string(caller) + ": a sphere of radius " + lubricated::detail::number(r) +
           " appeared during the run (the smallest at its start: " + lubricated::detail::number(r_start) +
           "): " + lubricated::liggghts::with_property_names(problem) +
           ". Use a smaller lubricatedGridSpacing, or lubricatedActivation");
  }
  const double reach = lubricated::liggghts::reach_fraction(coefficients_, ntypes_, is_wall_, r);
  neighbor->register_contact_dist_factor(1.0 + reach + lubricated::liggghts::approach_margin);
  if (comm->me == 0) {
    const std::string line = std::string(caller) + ": a sphere of radius " + lubricated::detail::number(r) +
                             " appeared (the smallest at the run's start: " + lubricated::detail::number(r_start) +
                             "); the film of lubricatedGridSpacing now raises the contact distance factor to " +
                             lubricated::detail::number(neighbor->contactDistanceFactor) + "\n";
    if (screen) fputs(line.c_str(), screen);
    if (logfile) fputs(line.c_str(), logfile);
  }
}

void NormalModel<LUBRICATED>::check_primitive_wall_list(const char *caller)
{
  auto *wall = static_cast<LAMMPS_NS::FixWallGran *>(hsetup_);
  const int wall_type = wall->atom_type_wall();
  if (wall->is_mesh_wall() || wall_type < 1 || wall_type > ntypes_) return;
  double r_max = 0.0, r_max_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    r_max = std::max(r_max, atom->radius[i]);
  MPI_Allreduce(&r_max, &r_max_all, 1, MPI_DOUBLE, MPI_MAX, world);
  double reach = 0.0;
  std::string how;
  for (int t = 1; t <= ntypes_; t++) {
    const lubricated::Coefficients &c = coefficients_[t * (ntypes_ + 1) + wall_type];
    if (!c.wet()) continue;
    if (c.grid_spacing > 0.0) {
      const double r = lubricated::Lubrication::grid_activation * c.grid_spacing;
      if (r > reach)
        reach = r, how = "2 x 0.75 lubricatedGridSpacing = 2 x 0.75 x " + lubricated::detail::number(c.grid_spacing);
    } else if (c.eps_activation > 0.0 && c.eps_activation * r_max_all > reach) {
      reach = c.eps_activation * r_max_all;
      how = "2 x lubricatedActivation x the largest radius = 2 x " + lubricated::detail::number(c.eps_activation) +
            " x " + lubricated::detail::number(r_max_all);
    }
  }
  if (neighbor->skin >= 2.0 * reach * (1.0 - 1e-12)) return;
  fail(std::string(caller) + ": the film reaches " + lubricated::detail::number(reach) +
       " from this primitive wall, but LIGGGHTS lists a sphere near a primitive wall only within the neighbor "
       "skin (" +
       lubricated::detail::number(neighbor->skin) +
       ") at a neighbor build and rebuilds after a sphere moved skin / 2, whatever the contact distance "
       "factor: the film would be missed for part of an approach. Use neighbor skin >= " +
       how + " = " + lubricated::detail::number(2.0 * reach) + ", or a mesh wall");
}

void NormalModel<LUBRICATED>::join_film_budget(const char *caller)
{
  double limit_pair = 0.0;
  std::string style_error;    // reported by read_coefficients already
  if (lubricated::liggghts::read_scalar(modify, "lubricatedLimitPair", caller, limit_pair, style_error) &&
      limit_pair != 0.0 && limit_pair != 1.0)
    fail(std::string(caller) + ": lubricatedLimitPair = " + lubricated::detail::number(limit_pair) +
         " must be 0 (the films of each sphere share its many-body budget, the default) or 1 "
         "(each film capped on its own)");
  bool wet = false;
  for (const lubricated::Coefficients &c : coefficients_)
    wet = wet || c.wet();
  std::vector<double> normal, bound;
  const bool network = network_loads(normal, bound);
  budget_ = lubricated::liggghts::FixLubricatedFilmBudget::find(lmp, !is_wall_ && (wet || network));
  budget_on_ = budget_ && wet;
  bound_dt_ = -1.0;
  if (!budget_) return;
  if (!is_wall_) {
    budget_->set_network(ntypes_, normal, bound, coefficients_);
    budget_->set_immovable_groups(integrate_bits_, hold_bits_);
  }
  if (!budget_on_) return;
  budget_->take_part(limit_pair == 1.0);
  if (is_wall_) {    // the films of the wall's type with each atom type
    auto *wall = static_cast<LAMMPS_NS::FixWallGran *>(hsetup_);
    const int wall_type = wall->atom_type_wall();
    const bool known = wall_type >= 1 && wall_type <= ntypes_;
    std::vector<lubricated::Lubrication> by_type(ntypes_ + 1);
    for (int t = 1; known && t <= ntypes_; t++)
      by_type[t] = models_[t * (ntypes_ + 1) + wall_type].lubrication;
    budget_->add_wall_films(by_type, wall->is_mesh_wall() || !known);    // unknown: no bound
  }
}

void NormalModel<LUBRICATED>::bound_film_shares()
{
  if (update->dt != dt_) build_models();
  bound_dt_ = update->dt;
  double *bound = budget_->bound_of_atoms();
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const double skin = neighbor->skin;
  const LAMMPS_NS::NeighList *list = pair_->list;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const lubricated::Lubrication &film = models_[type[i] * (ntypes_ + 1) + type[j]].lubrication;
      if (!film.active()) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double film_radius = lubricated::film_radius_pair(radius[i], radius[j]).value;
      const double reach = radius[i] + radius[j] + film.reach(film_radius) + skin;
      if (dx * dx + dy * dy + dz * dz >= reach * reach) continue;
      const double b = lubricated::film_share_bound(film, film_radius, pair_reduced_mass(i, j), dt_);
      bound[i] += b;
      if (newton_pair || j < nlocal) bound[j] += b;
    }
  }
  budget_->decide_skip();
}

bool NormalModel<LUBRICATED>::network_loads(std::vector<double> &normal, std::vector<double> &bound) const
{
  normal.assign(models_.size(), 0.0);
  bound.assign(models_.size(), 0.0);
  bool matters = false;
  for (int i = 1; i <= ntypes_; i++)
    for (int j = 1; j <= ntypes_; j++) {
      const int t = i * (ntypes_ + 1) + j;
      const lubricated::NormalModel &m = models_[t];
      normal[t] = lubricated::contact_load(m.step.stiffness_step, m.step.damping_step, dt_);
      bound[t] =
          std::max(normal[t], lubricated::contact_load(m.contact.stiffness_per_mass, m.contact.damping_per_mass, dt_));
      matters = matters || bound[t] > lubricated::network_check_load;
    }
  return matters;
}

void NormalModel<LUBRICATED>::build_models()
{
  dt_ = update->dt;
  models_ = lubricated::liggghts::build_models(coefficients_, ntypes_, is_wall_, dt_, message_);
  if (!message_.empty()) fail(message_);
  // The films' largest reach for bound_idle_pairs: 0.75 dx with a grid, else eps_al R.
  film_eps_max_ = film_reach_max_ = 0.0;
  for (const lubricated::NormalModel &m : models_) {
    const lubricated::Lubrication &film = m.lubrication;
    if (!film.active()) continue;
    if (film.grid_spacing > 0.0)
      film_reach_max_ = std::max(film_reach_max_, film.reach(0.0));
    else
      film_eps_max_ = std::max(film_eps_max_, film.eps_activation);
  }
  if (budget_ && !is_wall_) {    // a new time step: new network loads
    std::vector<double> normal, bound;
    network_loads(normal, bound);
    budget_->set_network(ntypes_, normal, bound, coefficients_);
  }
}

void NormalModel<LUBRICATED>::missed_approach(double u_n)
{
  if (warned_) return;
  warned_ = true;
  message_ = lubricated::liggghts::missed_approach_warning(u_n, dt_, neighbor->contactDistanceFactor);
  error->warning(FLERR, message_.c_str());
}

void NormalModel<LUBRICATED>::check_overlap(const SurfacesIntersectData &sidata, double gap, int t)
{
  const int i = sidata.i, j = sidata.j;
  if (!is_wall_ && immovable(i) && immovable(j)) return;    // neither can move
  const double radius = smaller_radius(sidata);
  const double fraction = lubricated::overlap_fraction(gap, radius);
  const lubricated::OverlapLevel level = lubricated::overlap_level(fraction);
  const bool deep = level == lubricated::OverlapLevel::error;
  if (level == lubricated::OverlapLevel::none || (deep ? overlap_deep_warned_ : overlap_warned_)) return;
  overlap_warned_ = true;
  overlap_deep_warned_ = deep;
  overlap_depth_ = deep ? INFINITY : lubricated::overlap_error_fraction;
  const std::string type_i = std::to_string(atom->type[i]), tag_i = std::to_string(atom->tag[i]);
  const std::string who = is_wall_
                              ? "model lubricated: atom " + tag_i + " (type " + type_i + ") and the wall of fix " +
                                    static_cast<LAMMPS_NS::FixWallGran *>(hsetup_)->id + " (wall/gran)"
                              : "pair gran model lubricated: atoms " + tag_i + " and " + std::to_string(atom->tag[j]) +
                                    " (types " + type_i + " " + std::to_string(atom->type[j]) + ")";
  // LIGGGHTS's properties: t_c = N_c dt at every time step, one value for all type pairs.
  const lubricated::ContactTimeNames names{"lubricatedContactTime", "lubricatedContactSteps", true, false};
  const std::string text =
      lubricated::overlap_message(who, gap, radius, fraction, coefficients_[t], dt_, false, is_wall_, names);
  error->warning(FLERR, text.c_str());
}

void NormalModel<LUBRICATED>::find_immovable_groups()
{
  integrate_bits_ = hold_bits_ = 0;
  for (int k = 0; k < modify->nfix; k++) {
    const LAMMPS_NS::Fix *fix = modify->fix[k];
    if (std::strcmp(fix->style, "freeze") == 0 || std::strcmp(fix->style, "move") == 0 ||
        (std::strcmp(fix->style, "setforce") == 0 && lubricated::liggghts::setforce_holds(modify->fix[k])))
      hold_bits_ |= fix->groupbit;
    else if (fix->time_integrate)
      integrate_bits_ |= fix->groupbit;
  }
}

}    // namespace ContactModels
}    // namespace LIGGGHTS
