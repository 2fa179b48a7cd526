/* ----------------------------------------------------------------------
   pair_style lubricated/springdashpot (see doc/pair_lubricated_springdashpot.rst)
------------------------------------------------------------------------- */

#include "pair_lubricated_springdashpot.h"

#include "unit_style/unit_style.h"
#include "vector_pairs.h"

#include "fix_step_velocity/fix_step_velocity.h"
#include "lubricated/check_setup.h"
#include "lubricated/film_budget.h"
#include "lubricated/film_solve.h"

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
#include <string>

using namespace LAMMPS_NS;
namespace lub = lubricated;

static constexpr const char *STYLE = "Pair style lubricated/springdashpot";

PairLubricatedSpringDashpot::PairLubricatedSpringDashpot(LAMMPS *lmp) :
    Pair(lmp), exchange(lmp, this), budget(lmp, exchange), contact_mass(lmp), network(lmp, exchange, STYLE)
{
  ContactMass::watch_setforce(lmp);    // again after a `clear`
  single_enable = 1;
  single_extra = 3;    // contact force, lubrication force, normalised gap
  svector = new double[single_extra];
  // compute pair: the pairs the last evaluation selected and, of those, the film-only ones;
  // under limit implicit the coupled solve's iterations and solved films (else 0).
  nextra = 4;
  pvector = new double[nextra]();
  finitecutflag = 1;
  restartinfo = 1;
  writedata = 1;
  set_comm_sizes();
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
  network.allocate(n);
  maxrad.assign(n + 1, 0.0);
  cutoff_given.assign((n + 1) * (n + 1), 0.0);
}

// The film budget: scales forward, loads reverse (1 value per atom); the contact masses
// forward (1); the contact-network check: its sums both ways (lub::network_values); the coupled
// film solve: 6 values per atom both ways, and 36 in reverse (film_solve.h).
void PairLubricatedSpringDashpot::set_comm_sizes()
{
  comm_forward = film_solve.on ? std::max(lub::network_values, lub::film_dofs) : lub::network_values;
  comm_reverse = film_solve.on ? std::max(lub::network_values, 36) : lub::network_values;
  // The solve sends its sums back with newton pair off too (a film with a ghost partner is
  // solved by one of the two ranks that hold it).
  comm_reverse_off = film_solve.on ? 36 : 0;
}

// pair_style lubricated/springdashpot [vector yes|no] [limit atom|pair|implicit] [trim yes|no]
//                                     [tolerance T] [iterations N] (the last two with limit implicit)
void PairLubricatedSpringDashpot::settings(int narg, char **arg)
{
  require_supported_units(lmp, STYLE);
  vector_enabled = true;
  limit_per_atom = true;
  trim_enabled = true;
  film_solve = FilmSolveSettings();
  bool solve_keywords = false;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string key = arg[iarg];
    if (key != "vector" && key != "limit" && key != "trim" && key != "tolerance" && key != "iterations")
      error->all(FLERR,
                 "{}: unknown keyword '{}' (allowed: vector yes|no, limit atom|pair|implicit, trim yes|no, "
                 "tolerance T, iterations N; coefficients go in pair_coeff)",
                 STYLE, key);
    const char *allowed = key == "limit"        ? "atom, pair or implicit"
                          : key == "tolerance"  ? "a number in (0, 1)"
                          : key == "iterations" ? "an integer >= 1"
                                                : "yes or no";
    if (iarg + 1 >= narg) error->all(FLERR, "{}: keyword {} needs a value ({})", STYLE, key, allowed);
    const std::string value = arg[iarg + 1];
    if (key == "limit") {
      if (value != "atom" && value != "pair" && value != "implicit")
        error->all(FLERR, "{}: limit = {} is not allowed (atom, pair or implicit)", STYLE, value);
      limit_per_atom = value != "pair";
      film_solve.on = value == "implicit";
      continue;
    }
    if (key == "tolerance" || key == "iterations") {
      parse_film_solve_keyword(key, value);
      solve_keywords = true;
      continue;
    }
    if (value != "yes" && value != "no") error->all(FLERR, "{}: {} = {} is not allowed (yes or no)", STYLE, key, value);
    (key == "vector" ? vector_enabled : trim_enabled) = value == "yes";
  }
  if (solve_keywords && !film_solve.on)
    error->all(FLERR, "{}: tolerance and iterations belong to limit implicit (the coupled film solve)", STYLE);
  set_comm_sizes();
}

void PairLubricatedSpringDashpot::parse_film_solve_keyword(const std::string &key, const std::string &value)
{
  if (key == "tolerance") {
    double t = 0.0;
    if (!lub::detail::to_number(value, t) || !(t > 0.0 && t < 1.0))
      error->all(FLERR, "{}: tolerance = {} is not allowed (a number in (0, 1))", STYLE, value);
    film_solve.tolerance = t;
    return;
  }
  double n = 0.0;
  if (!lub::detail::to_number(value, n) || !(n >= 1.0 && n <= 1e9) || n != std::floor(n))
    error->all(FLERR, "{}: iterations = {} is not allowed (an integer from 1 to 1e9)", STYLE, value);
  film_solve.max_iterations = static_cast<int>(n);
}

// One int: bit 0 vector yes, bit 1 limit pair, bit 2 trim no, bit 3 a cutoff follows each type
// pair's coefficients, bit 4 limit implicit, then its tolerance (double) and iterations (int)
// follow (files written before `limit`, `trim`, `cutoff` or `implicit` read as atom, yes and
// cutoffs from the radii).
void PairLubricatedSpringDashpot::write_restart_settings(FILE *fp)
{
  const int flag = (vector_enabled ? 1 : 0) | (limit_per_atom ? 0 : 2) | (trim_enabled ? 0 : 4) |
                   (any_cutoff_given() ? 8 : 0) | (film_solve.on ? 16 : 0) | values_with_rollfilm;
  fwrite(&flag, sizeof(int), 1, fp);
  if (!film_solve.on) return;
  fwrite(&film_solve.tolerance, sizeof(double), 1, fp);
  fwrite(&film_solve.max_iterations, sizeof(int), 1, fp);
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
  // Files written before rollfilm (the last keyword) hold one value less per type pair.
  restart_values = (flag & values_with_rollfilm) ? lub::Coefficients::packed_size : lub::Coefficients::packed_size - 1;
  film_solve = FilmSolveSettings();
  film_solve.on = (flag & 16) != 0;
  if (film_solve.on) {
    if (comm->me == 0) {
      utils::sfread(FLERR, &film_solve.tolerance, sizeof(double), 1, fp, nullptr, error);
      utils::sfread(FLERR, &film_solve.max_iterations, sizeof(int), 1, fp, nullptr, error);
    }
    MPI_Bcast(&film_solve.tolerance, 1, MPI_DOUBLE, 0, world);
    MPI_Bcast(&film_solve.max_iterations, 1, MPI_INT, 0, world);
  }
  set_comm_sizes();
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

void PairLubricatedSpringDashpot::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  trim_list_if_built();
  // A set-up that continues the last run evaluates as its last step did (fix_step_velocity.h);
  // not with rigid bodies or immovable atoms, whose velocities the reconstruction does not know.
  continued = step_velocity && step_velocity->continues() && !contact_mass.holds_or_rigid();
  step_velocities_used = !update->setupflag || continued;
  overlap_check_due = update->setupflag || update->ntimestep % overlap_check_interval == 0;
  if (update->setupflag) network.find_participants();
  if (inverse_mass_on && (neighbor->ago == 0 || update->setupflag)) update_inverse_mass();
  budget.begin_step(list, {models.data(), max_reach.data(), ntypes_alloc + 1});
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
  finish_film_budget();
  check_network();
  pvector[0] = static_cast<double>(selected_pairs);
  pvector[1] = static_cast<double>(film_only_pairs);
  // compute pair sums over ranks: the iterations (the same on every rank) counted once.
  pvector[2] = comm->me == 0 ? budget.solve_iterations() : 0.0;
  pvector[3] = static_cast<double>(budget.solved_films());
  if (vflag_fdotr) virial_fdotr_compute();
}

// The film budget's pass after the loops; under limit implicit with the velocities and the kick
// time of the loops' films (pair_loop), which the coupled solve takes.
void PairLubricatedSpringDashpot::finish_film_budget()
{
  const double *inverse = inverse_mass_on ? inverse_mass.data() : nullptr;
  if (!film_solve.on) {
    budget.finish(inverse, evflag ? this : nullptr);
    return;
  }
  const FilmBudget::StepInputs step{continued ? step_velocity->velocity() : atom->v,
                                    continued ? step_velocity->spin() : atom->omega,
                                    lub::film_kick_time(update->dt, update->setupflag && !continued, false), inverse};
  budget.finish(inverse, evflag ? this : nullptr, &step);
}

// The contact-network check of this step, if due, once the films are final: a contact whose own
// film the coupled solve took counts with the relieved load (contact_network.h).
void PairLubricatedSpringDashpot::check_network()
{
  if (network_candidates < 0) return;
  const int n = network_candidates;
  network_candidates = -1;
  network.check({loop_lists.candidate_i.data(), loop_lists.candidate_j.data(), n,
                 inverse_mass_on ? inverse_mass.data() : nullptr, midpoint, coeffs.data(), budget.solved_now()});
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
      lub::Coefficients().pack(buf);    // the defaults of values the file does not hold
      if (me == 0) utils::sfread(FLERR, buf, sizeof(double), restart_values, fp, nullptr, error);
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
  const double doubles = maxrad.capacity() + max_reach.capacity() + inverse_mass.capacity();
  return Pair::memory_usage() + coeffs.capacity() * sizeof(lub::Coefficients) +
         models.capacity() * sizeof(lub::ContactModel) + doubles * sizeof(double) + loop_lists.memory_usage() +
         budget.memory_usage() + network.memory_usage();
}

double PairLubricatedSpringDashpot::LoopLists::memory_usage() const
{
  const double ints = candidate_i.capacity() + candidate_j.capacity() + candidate_jj.capacity() + film_i.capacity() +
                      film_j.capacity() + group_count.capacity() + group_keys.capacity();
  return ints * sizeof(int) + step_reach.capacity() * sizeof(double);
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
