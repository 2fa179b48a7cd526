/* ----------------------------------------------------------------------
   fix fluid/drag: the Basset history per atom (src/lubricated/fluid_inertia.h). Each atom of
   the group carries its window and tail modes, which migrate with it and go into restart
   files, so that a restarted run continues the history exactly. A step commits the last
   evaluation in pre_force, which a set-up does not call: a set-up that evaluates the forces
   of a step again (a run that continues, a restart) leaves the history as it was. Steps of
   unequal length (fix dt/reset, timestep between runs) keep their lengths (HistorySteps,
   global), so that the history stays on the true times. The global restart data carry them,
   and (also without history) the last solid fraction where every > 1.
------------------------------------------------------------------------- */

#include "fix_fluid_drag.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

static constexpr const char *STYLE = "Fix fluid/drag";

void FixFluidDrag::setup_history()
{
  basset = lubricated::BassetHistory(history_window, history_modes, 1.0);    // the layout; rates in init()
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange = basset.size();
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nmax; i++)
    set_arrays(i);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

void FixFluidDrag::lay_out_tail(double dt)
{
  history_dt = dt;
  basset = lubricated::BassetHistory(history_window, history_modes, history_dt);
  if (!history_begun) history_steps = lubricated::HistorySteps(history_window, dt);    // else kept
  step_bound.resize(history_window + 2);
  step_weight.resize(history_window + 1);
  step_decay.resize(history_modes);
  step_feed.resize(history_modes);
  if (finite_re && !mei_adrian.fits(basset))
    mei_adrian = lubricated::MeiAdrianKernel(basset);    // a table: built once per layout
}

void FixFluidDrag::pre_force(int /*vflag*/)
{
  // The first step commits only the set-up's end values: the window and tail are still empty,
  // so a step changed since init() (fix dt/reset's set-up) lays the tail out anew, exactly.
  if (!history_begun) {
    if (update->dt != history_dt) lay_out_tail(update->dt);
    history_begun = true;
    evaluated_dt = update->dt;    // no step behind the set-up's end values
  }
  // Later, steps that change (fix dt/reset, timestep between runs) keep their lengths.
  const bool uniform = evaluated_dt == history_dt && update->dt == history_dt && history_steps.uniform(history_dt);
  history_steps.advance(evaluated_dt, update->dt, basset.tail(), step_decay.data(), step_feed.data());
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (uniform)
      basset.commit(history_state[i]);
    else
      basset.commit(history_state[i], step_decay.data(), step_feed.data());
  }
}

// Once per evaluation: the window's weights where its steps differ from the layout's, and the
// step whose end values this evaluation keeps (a set-up only keeps an atom's first ones).
void FixFluidDrag::weigh_history_steps()
{
  const double dt = update->dt;
  steps_uniform = dt == history_dt && history_steps.uniform(history_dt);
  if (!steps_uniform) {
    history_steps.bounds(dt, step_bound.data());
    lubricated::window_weights(history_window, step_bound.data(), step_weight.data());
  }
  if (!update->setupflag || evaluated_dt == 0.0) evaluated_dt = dt;
}

void FixFluidDrag::grow_arrays(int nmax)
{
  memory->grow(history_state, nmax, basset.size(), "fluid/drag:history");
}

void FixFluidDrag::copy_arrays(int i, int j, int /*delflag*/)
{
  std::memcpy(history_state[j], history_state[i], basset.size() * sizeof(double));
}

void FixFluidDrag::set_arrays(int i)
{
  std::memset(history_state[i], 0, basset.size() * sizeof(double));
}

int FixFluidDrag::pack_exchange(int i, double *buf)
{
  std::memcpy(buf, history_state[i], basset.size() * sizeof(double));
  return basset.size();
}

int FixFluidDrag::unpack_exchange(int nlocal, double *buf)
{
  std::memcpy(history_state[nlocal], buf, basset.size() * sizeof(double));
  return basset.size();
}

int FixFluidDrag::pack_restart(int i, double *buf)
{
  buf[0] = basset.size() + 1;
  std::memcpy(buf + 1, history_state[i], basset.size() * sizeof(double));
  return basset.size() + 1;
}

void FixFluidDrag::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  if (static_cast<int>(extra[nlocal][m]) != basset.size() + 1)
    error->one(FLERR, "{}: the history in the restart file has another size (window or tail changed)", STYLE);
  std::memcpy(history_state[nlocal], &extra[nlocal][m + 1], basset.size() * sizeof(double));
}

int FixFluidDrag::size_restart(int /*i*/)
{
  return basset.size() + 1;
}

int FixFluidDrag::maxsize_restart()
{
  return basset.size() + 1;
}

// Global restart data, as doubles: a format mark -2 (-1: without the steps' lengths; older
// files begin with the window, >= 1), then the window and tail modes (0 0 without history) and
// the step the tail is laid out for, the step of the last solid fraction (-1: none) and the
// number of bins and their phi (0 and none unless every > 1, when a restart between multiples
// of every needs the last phi); then, with history, the step of the last kept evaluation and the
// lengths of the window's steps.
void FixFluidDrag::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> data = {-2.0, history ? static_cast<double>(history_window) : 0.0,
                              history ? static_cast<double>(history_modes) : 0.0, history ? history_dt : 0.0,
                              static_cast<double>(last_fraction_step)};
  const bool fraction = stores_fraction() && last_fraction_step >= 0;
  data.push_back(fraction ? static_cast<double>(bin_solid.size()) : 0.0);
  if (fraction) data.insert(data.end(), bin_solid.begin(), bin_solid.end());
  if (history) {
    data.push_back(evaluated_dt);
    data.insert(data.end(), history_steps.lengths().begin(), history_steps.lengths().end());
  }
  const int size = static_cast<int>(data.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data.data(), sizeof(double), data.size(), fp);
}

void FixFluidDrag::restart(char *buf)
{
  double head[6];
  std::memcpy(head, buf, 3 * sizeof(double));
  const bool old_format = head[0] > 0.0;    // window, tail, history_dt
  if (!old_format) std::memcpy(head, buf, 6 * sizeof(double));
  const double *saved = old_format ? head : head + 1;
  const int window = static_cast<int>(saved[0]), modes = static_cast<int>(saved[1]);
  if (history && window > 0) {
    if (window != history_window || modes != history_modes)
      error->all(FLERR,
                 "{}: the restart file's history has window {} and tail {}, the fix window {} and tail {}: "
                 "give the same values",
                 STYLE, window, modes, history_window, history_modes);
    history_dt = saved[2];
    history_begun = true;
    history_steps = lubricated::HistorySteps(history_window, history_dt);    // older files: equal steps
    evaluated_dt = history_dt;
  }
  if (old_format) return;
  const auto count = static_cast<std::size_t>(head[5]);
  if (head[0] < -1.5 && history && window > 0) {
    std::vector<double> steps(history_window + 1);
    std::memcpy(steps.data(), buf + (6 + count) * sizeof(double), steps.size() * sizeof(double));
    evaluated_dt = steps[0];
    history_steps.set_lengths(steps.data() + 1);
  }
  if (stores_fraction() && head[4] >= 0.0 && count == bin_solid.size()) {    // other bins: recomputed
    std::memcpy(bin_solid.data(), buf + 6 * sizeof(double), count * sizeof(double));
    last_fraction_step = static_cast<bigint>(head[4]);
  }
}
