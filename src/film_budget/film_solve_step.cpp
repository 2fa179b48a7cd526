/* ----------------------------------------------------------------------
   The coupled film solve of pair_style lubricated/springdashpot (film_solve_step.h)
------------------------------------------------------------------------- */

#include "film_solve_step.h"

#include "lubricated/film_link.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "fix.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

using namespace LAMMPS_NS;
namespace lub = lubricated;

void FilmSolveStep::configure(const FilmSolveSettings &settings)
{
  options.tolerance = settings.tolerance;
  options.max_iterations = settings.max_iterations;
}

// The links of the records in the solve, those this rank solves first: every film once over all
// ranks (with newton off a film with a ghost partner is recorded on both ranks; the one holding
// the smaller tag solves it), the walls' after this rank's pairs. Returns how many are solved here.
int FilmSolveStep::collect_links(const Records &records, const double *scale, const FilmBudget::TypeTables &tables)
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  links.clear();
  link_record.clear();
  int n_solved = 0;
  for (int pass = 0; pass < 2; pass++) {
    for (int r = 0; r < records.count; r++) {
      const int i = records.i[r], j = records.j[r];
      if (std::min(scale[i], scale[j]) == 1.0) continue;
      const bool here = newton_pair || j < nlocal || tag[i] < tag[j];
      if (here != (pass == 0)) continue;
      const lub::Vec3 del{x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double r_ij = std::sqrt(lub::dot(del, del));
      const lub::ContactModel &model = tables.models[type[i] * tables.stride + type[j]];
      links.push_back(lub::pair_film_link(model, i, j, lub::scaled(del, 1.0 / r_ij), r_ij, radius[i], radius[j]));
      link_record.push_back(r);
      n_solved += here;
    }
    if (pass == 0) n_solved += collect_wall_links(scale);
  }
  return n_solved;
}

// The walls' films of owned atoms over budget (their links act on owned atoms only).
int FilmSolveStep::collect_wall_links(const double *scale)
{
  wall_links.clear();
  int added = 0;
  for (FilmBudgetParticipant *wall : walls) {
    const int first = static_cast<int>(links.size());
    const int count = wall->add_film_links(scale, links);
    if (count == 0) continue;
    wall_links.push_back({wall, first, count});
    link_record.insert(link_record.end(), count, -1);
    added += count;
  }
  return added;
}

// Per owned and ghost atom: inverse mass (the contact masses' where some atom is immovable),
// inverse moment of inertia (0 where immovable) and the velocities w = (v, omega) the
// evaluation took (the ghosts' as the engine communicated them).
void FilmSolveStep::gather_atoms(const FilmBudget::StepInputs &step)
{
  const int nall = atom->nlocal + atom->nghost;
  const double *rmass = atom->rmass, *radius = atom->radius;
  inverse_mass.resize(nall), inverse_inertia.resize(nall);
  velocity.resize(lub::film_dofs * nall), increment.resize(lub::film_dofs * nall);
  for (int k = 0; k < nall; k++) {
    inverse_mass[k] = step.inverse_mass ? step.inverse_mass[k] : 1.0 / rmass[k];
    inverse_inertia[k] = inverse_mass[k] > 0.0 ? 1.0 / lub::sphere_inertia(rmass[k], radius[k]) : 0.0;
    double *w = &velocity[lub::film_dofs * k];
    for (int d = 0; d < 3; d++)
      w[d] = step.v[k][d], w[3 + d] = step.omega[k][d];
  }
}

// The step-exact rolling film the loops applied to record r: its torque on i (on j the opposite).
static lub::Vec3 recorded_roll(const FilmSolveStep::Records &records, int r)
{
  if (!records.roll) return {};
  return {records.roll[3 * r], records.roll[3 * r + 1], records.roll[3 * r + 2]};
}

// F of the solve, per atom: the forces and torques the pair loops gave this evaluation (the
// contacts, the films outside the solve) less the step-exact films of the solved links, summed on
// the owners. With F = 0 a solved film would meet a contact's push of this step only at the next
// evaluation, as a separating velocity it resists: at stiff contacts that pulls the pair
// together. The forces of fixes (drag, gravity) come after the pair style and stay explicit.
void FilmSolveStep::gather_other_forces(const Records &records)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, newton_pair = force->newton_pair;
  double **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  other_force.assign(lub::film_dofs * nall, 0.0);
  // Without newton the ghosts' force entries are not the pair style's (not even cleared).
  const int accumulated = newton_pair ? nall : nlocal;
  for (int k = 0; k < accumulated; k++)
    for (int d = 0; d < 3; d++)
      other_force[lub::film_dofs * k + d] = f[k][d], other_force[lub::film_dofs * k + 3 + d] = torque[k][d];
  for (std::size_t k = 0; k < links.size(); k++) {
    const lub::FilmLink &link = links[k];
    if (link.j < 0) continue;    // a wall's film is applied by its fix, after the solve
    const int r = link_record[k], i = link.i, j = link.j;
    const lub::Vec3 shear = records.shear
                                ? lub::Vec3{records.shear[3 * r], records.shear[3 * r + 1], records.shear[3 * r + 2]}
                                : lub::Vec3{};
    const lub::Vec3 applied = lub::plus(lub::scaled(link.normal, records.film[r]), shear);
    const lub::Vec3 nxs = lub::cross(link.normal, shear);    // the applied torques were -R n x F_t
    const lub::Vec3 roll = recorded_roll(records, r);
    lub::film_add(&other_force[lub::film_dofs * i], applied, -1.0);
    lub::film_add(&other_force[lub::film_dofs * i + 3], nxs, radius[i]);
    lub::film_add(&other_force[lub::film_dofs * i + 3], roll, -1.0);
    if (newton_pair || j < nlocal) {
      lub::film_add(&other_force[lub::film_dofs * j], applied, 1.0);
      lub::film_add(&other_force[lub::film_dofs * j + 3], nxs, radius[j]);
      lub::film_add(&other_force[lub::film_dofs * j + 3], roll, 1.0);
    }
  }
  if (newton_pair) exchange.reverse(other_force.data(), lub::film_dofs);
}

void FilmSolveStep::start_run(const std::vector<FilmBudgetParticipant *> &participants)
{
  walls.clear();
  for (FilmBudgetParticipant *participant : participants)
    if (participant->wet()) walls.push_back(participant);
  warned = false;
  drag_fix = nullptr;
  for (int k = 0; k < modify->nfix && !drag_fix; k++)
    drag_fix = dynamic_cast<ImplicitDragParticipant *>(modify->fix[k]);
}

// The drag of drag_fix on the owned atoms into F (at w) and into the matrix (implicit_drag.h),
// and the inertia that fix solves for beyond the contact mass into the atoms' masses.
bool FilmSolveStep::add_implicit_drag()
{
  if (!drag_fix || !drag_fix->drag_is_implicit()) return false;
  const int nlocal = atom->nlocal;
  drag.assign(nlocal, 0.0), rotational_drag.assign(nlocal, 0.0);
  for (int k = 0; k < nlocal; k++) {
    double *w = &velocity[lub::film_dofs * k], *f = &other_force[lub::film_dofs * k];
    const ImplicitDragParticipant::LinearDrag d = drag_fix->linear_drag(k, w);
    drag[k] = d.drag, rotational_drag[k] = d.rotational_drag;
    for (int c = 0; c < 3; c++) {
      f[c] += d.drag * (d.fluid_velocity[c] - w[c]);
      f[3 + c] += d.rotational_drag * (d.fluid_spin[c] - w[3 + c]);
    }
    if (d.solved_mass > 0.0 && inverse_mass[k] > 0.0) inverse_mass[k] = 1.0 / (1.0 / inverse_mass[k] + d.solved_mass);
  }
  return true;
}

void FilmSolveStep::solve(const Records &records, const double *scale, const FilmBudget::TypeTables &tables,
                          const FilmBudget::StepInputs &step, FilmBudget::Tally *tally)
{
  start_from_last_steps();    // before gather_atoms lays the increments out anew
  const int n_solved = collect_links(records, scale, tables);
  gather_atoms(step);
  gather_other_forces(records);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  lub::FilmAtoms atoms;
  atoms.owned = nlocal, atoms.total = nall;
  atoms.inverse_mass = inverse_mass.data(), atoms.inverse_inertia = inverse_inertia.data();
  atoms.radius = atom->radius;
  const bool implicit_drag = add_implicit_drag();
  if (implicit_drag) atoms.drag = drag.data(), atoms.rotational_drag = rotational_drag.data();
  lub::FilmComm film_comm;
  film_comm.forward = [this](double *data, int width) { exchange.forward(data, width); };
  film_comm.reverse = [this](double *data, int width) { exchange.reverse(data, width); };
  film_comm.sum = [this](double *values, int count) {
    MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, world);
  };
  const lub::FilmSolveResult result = solver.solve(atoms, links.data(), n_solved, step.kick_time, velocity.data(),
                                                   other_force.data(), increment.data(), options, film_comm);
  iterations = result.iterations, solved = n_solved;
  if (!result.converged && !warned) {
    warned = true;
    if (comm->me == 0)
      error->warning(FLERR,
                     "Pair style lubricated/springdashpot: the coupled film solve (limit implicit) did not "
                     "converge to tolerance {} within iterations {} (relative residual {:.3g} after {}); "
                     "raise iterations or tolerance, or shorten the time step (warned once per run)",
                     options.tolerance, options.max_iterations, result.residual, result.iterations);
  }
  if (implicit_drag) drag_fix->take_increments(increment.data(), nlocal, update->ntimestep);
  // w' = w + x on owned and ghost atoms (the solver forwarded x).
  for (int e = 0; e < lub::film_dofs * nall; e++)
    velocity[e] += increment[e];
  apply_solved_films(records, atoms, tally);
  apply_solved_wall_films(atoms);
}

// Where the last steps were solved in a row (no set-up between), the solve starts from their
// increments extrapolated (film_solve.h): along a trajectory they change little from step to
// step, and the iterations fall to a fraction. Across a list build, which may reorder the atoms,
// each atom's increments follow it by tag. The preconditioner's blocks are kept along such a
// chain too, for blocks_kept_steps, while no atom changed its index on any rank.
void FilmSolveStep::start_from_last_steps()
{
  const int nlocal = atom->nlocal;
  // The same on every rank: the start and the blocks decide which communications the solve makes.
  const int in_order = neighbor->ago > 0 && nlocal == last_nlocal;
  int here[2] = {!update->setupflag && update->ntimestep == last_solve_step + 1 && (in_order || atom->tag_enable),
                 in_order},
      everywhere[2] = {0, 0};
  MPI_Allreduce(here, everywhere, 2, MPI_INT, MPI_MIN, world);
  known_increments = everywhere[0] ? std::min(known_increments + 1, 2) : 0;
  if (known_increments > 0 && !in_order) carry_increments_by_tag();
  last_solve_step = update->ntimestep, last_nlocal = nlocal;
  if (atom->tag_enable) last_tags.assign(atom->tag, atom->tag + nlocal);
  const int n = lub::film_dofs * nlocal;
  increment.resize(std::max<std::size_t>(increment.size(), n));
  if (known_increments == 1) previous_increment.resize(n);
  options.warm_start = lub::film_increment_guess(increment.data(), previous_increment.data(), n, known_increments);
  // The preconditioner's blocks change with the films as slowly: kept along the same chain of
  // solves with the atoms in their order, made again every blocks_kept_steps.
  options.reuse_blocks = known_increments > 0 && everywhere[1] && update->ntimestep - blocks_step < blocks_kept_steps;
  if (!options.reuse_blocks) blocks_step = update->ntimestep;
}

// The last steps' increments of the owned atoms (x_{n-1} in increment, x_{n-2} in
// previous_increment), laid out in the order of last_tags, put in the atoms' present order; an
// atom new to this rank starts from 0 (the solver scales the guess at best, film_solve.h).
void FilmSolveStep::carry_increments_by_tag()
{
  constexpr int dofs = lub::film_dofs;
  const int nlocal = atom->nlocal, old = static_cast<int>(last_tags.size());
  std::unordered_map<tagint, int> where;
  where.reserve(old);
  for (int k = 0; k < old; k++)
    where.emplace(last_tags[k], k);
  const bool two = known_increments == 2;
  std::vector<double> last(dofs * nlocal, 0.0), before(two ? dofs * nlocal : 0, 0.0);
  for (int i = 0; i < nlocal; i++) {
    const auto found = where.find(atom->tag[i]);
    if (found == where.end()) continue;
    std::copy_n(&increment[dofs * found->second], dofs, &last[dofs * i]);
    if (two) std::copy_n(&previous_increment[dofs * found->second], dofs, &before[dofs * i]);
  }
  increment.swap(last);
  if (two) previous_increment.swap(before);
}

// Per link: its force at w' (the solved film) in place of the step-exact film the loops applied,
// on i and j (Newton's third law, as the pair loops apply it: on j where newton is on or j is
// owned), with torques -R n x F_t and the rolling film's, and tallied.
void FilmSolveStep::apply_solved_films(const Records &records, const lub::FilmAtoms &atoms, FilmBudget::Tally *tally)
{
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  for (std::size_t k = 0; k < links.size(); k++) {
    const lub::FilmLink &link = links[k];
    if (link.j < 0) continue;
    const int r = link_record[k], i = link.i, j = link.j;
    const lub::FilmLinkForce solved = lub::film_link_force(link, atoms, velocity.data(), false);
    const lub::Vec3 shear = records.shear
                                ? lub::Vec3{records.shear[3 * r], records.shear[3 * r + 1], records.shear[3 * r + 2]}
                                : lub::Vec3{};
    const lub::Vec3 applied = lub::plus(lub::scaled(link.normal, records.film[r]), shear);
    const lub::Vec3 change = lub::minus(solved.force_i, applied);
    // The step-exact shear film's torques were -R n x F_t on both atoms, the rolling film's T on i
    // and -T on j.
    const lub::Vec3 nxs = lub::cross(link.normal, shear), roll = recorded_roll(records, r);
    const lub::Vec3 torque_i = lub::minus(lub::plus(solved.torque_i, lub::scaled(nxs, radius[i])), roll);
    const lub::Vec3 torque_j = lub::plus(lub::plus(solved.torque_j, lub::scaled(nxs, radius[j])), roll);
    f[i][0] += change.x, f[i][1] += change.y, f[i][2] += change.z;
    torque[i][0] += torque_i.x, torque[i][1] += torque_i.y, torque[i][2] += torque_i.z;
    if (newton_pair || j < nlocal) {
      f[j][0] -= change.x, f[j][1] -= change.y, f[j][2] -= change.z;
      torque[j][0] += torque_j.x, torque[j][1] += torque_j.y, torque[j][2] += torque_j.z;
    }
    if (tally)
      tally->tally_film_correction_xyz(i, j, change.x, change.y, change.z, x[i][0] - x[j][0], x[i][1] - x[j][1],
                                       x[i][2] - x[j][2]);
  }
}

// Per wall link: its force and torque on the atom at w' (the wall's velocity counted), handed to
// its fix, which applies them in place of its step-exact films (and tallies them).
void FilmSolveStep::apply_solved_wall_films(const lub::FilmAtoms &atoms)
{
  for (const WallLinks &range : wall_links) {
    wall_solved.resize(range.count);
    for (int k = 0; k < range.count; k++)
      wall_solved[k] = lub::film_link_force(links[range.first + k], atoms, velocity.data(), true);
    range.wall->take_solved_films(wall_solved.data(), range.count);
  }
}

lub::SolvedFilms FilmSolveStep::solved_at(bigint step) const
{
  lub::SolvedFilms solved;
  if (last_solve_step != step) return solved;
  solved.links = links.data(), solved.count = static_cast<int>(links.size());
  return solved;
}

double FilmSolveStep::memory_usage() const
{
  return links.capacity() * sizeof(lub::FilmLink) + link_record.capacity() * sizeof(int) +
         (inverse_mass.capacity() + inverse_inertia.capacity() + velocity.capacity() + other_force.capacity() +
          increment.capacity() + previous_increment.capacity()) *
             sizeof(double) +
         wall_solved.capacity() * sizeof(lub::FilmLinkForce) + last_tags.capacity() * sizeof(tagint);
}
