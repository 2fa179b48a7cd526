/* ----------------------------------------------------------------------
   fix LUBRICATED_HISTORY (see fix_contact_history.h)
------------------------------------------------------------------------- */

#include "fix_contact_history.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "utils.h"

#include <algorithm>

using namespace LAMMPS_NS;
using namespace FixConst;

FixContactHistory::FixContactHistory(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (narg != 4) error->all(FLERR, "Illegal fix LUBRICATED_HISTORY command: expected nvalue");
  nvalue = utils::inumeric(FLERR, arg[3], false, lmp);
  if (nvalue < 1) error->all(FLERR, "Fix LUBRICATED_HISTORY: nvalue = {} must be >= 1", nvalue);
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange_dynamic = 1;
  maxexchange = 1;
  comm_reverse = 1;    // the ghosts' record counts (REVERSE_COUNTS)
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixContactHistory::~FixContactHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

int FixContactHistory::setmask()
{
  return PRE_EXCHANGE | MIN_PRE_EXCHANGE | POST_NEIGHBOR | MIN_POST_NEIGHBOR | POST_RUN;
}

void FixContactHistory::init()
{
  if (atom->tag_enable == 0) error->all(FLERR, "Pair style lubricated/springdashpot with friction requires atom IDs");
}

void FixContactHistory::setup_pre_exchange()
{
  store_from_list();
}
void FixContactHistory::pre_exchange()
{
  store_from_list();
}
void FixContactHistory::min_pre_exchange()
{
  store_from_list();
}
void FixContactHistory::setup_post_neighbor()
{
  map_to_list();
}
void FixContactHistory::post_neighbor()
{
  map_to_list();
}
void FixContactHistory::min_post_neighbor()
{
  map_to_list();
}
// Between runs the per-atom records are the truth: they migrate with the atoms that
// write_restart, write_data, delete_atoms or the next set-up move and reorder, while the list and
// its flat arrays then go stale. A run with `pre no` (or `run N every M`) has no set-up, and its
// list and flat arrays go on from the last run's: the pair writes its new history there, which
// the first store of that run must keep. So the list's atom order is remembered here, and the
// stores before the next mapping take the flat arrays only while it holds on every rank.
void FixContactHistory::post_run()
{
  store_from_list();
  order_at_run_end = atom_order();
  check_order = true;
}

// The tags of the owned and ghost atoms in index order, hashed (FNV-1a): the list's entries mean
// the same pairs as long as it is unchanged.
std::uint64_t FixContactHistory::atom_order() const
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  std::uint64_t hash = 1469598103934665603ull;
  auto mix = [&hash](std::uint64_t word) { hash = (hash ^ word) * 1099511628211ull; };
  mix(static_cast<std::uint64_t>(nlocal));
  mix(static_cast<std::uint64_t>(nall));
  for (int i = 0; i < nall; i++)
    mix(static_cast<std::uint64_t>(atom->tag[i]));
  return hash;
}

// Whether the flat arrays still belong to the atoms as they are now (see post_run), the same
// answer on every rank (a store communicates).
bool FixContactHistory::list_still_current()
{
  if (!check_order) return true;
  int changed = atom_order() != order_at_run_end ? 1 : 0, changed_anywhere = 0;
  MPI_Allreduce(&changed, &changed_anywhere, 1, MPI_INT, MPI_MAX, world);
  return changed_anywhere == 0;
}

// Entry of the next partner of atom i, whose room store_from_list reserved (count the cursor).
void FixContactHistory::add(int i, tagint other, const double *v, double sign)
{
  double *out = &pool[record_first[i] + static_cast<std::size_t>(record_count[i]++) * entry()];
  out[0] = ubuf(other).d;
  for (int k = 0; k < nvalue; k++)
    out[1 + k] = sign * v[k];
}

// Room for `count` entries of atom i at the end of the pool (an atom migrating in or read from a
// restart file): the pool grows by 1/8 at least, never to twice its size.
double *FixContactHistory::append_record(int i, int count)
{
  const std::size_t at = pool.size(), need = at + static_cast<std::size_t>(count) * entry();
  if (need > pool.capacity()) pool.reserve(std::max(need, pool.capacity() + pool.capacity() / 8));
  pool.resize(need);
  record_first[i] = static_cast<int>(at);
  record_count[i] = count;
  return pool.data() + at;
}

// Flat list arrays -> per-atom records of both atoms of every touching pair: counted first (the
// ghosts' counts added to their owners', newton on), then written in the room so reserved, the
// ghosts' sent to their owners.
void FixContactHistory::store_from_list()
{
  if (!mapped || !list) return;
  if (!list_still_current()) {
    mapped = false;
    return;
  }
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const bool newton = force->newton_pair != 0;
  std::fill(record_count.begin(), record_count.begin() + nall, 0);
  auto each_touching = [&](auto &&pair) {
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int *jlist = list->firstneigh[i];
      const char *t = touched(i);
      for (int jj = 0; jj < list->numneigh[i]; jj++)
        if (t[jj]) pair(i, jlist[jj] & NEIGHMASK, jj);
    }
  };
  // With newton off a ghost partner's own rank holds the pair too and stores it there.
  each_touching([&](int i, int j, int) {
    record_count[i]++;
    if (j < nlocal || newton) record_count[j]++;
  });
  if (newton) {
    reverse_what = REVERSE_COUNTS;
    comm->reverse_comm(this);
  }
  std::size_t total = 0;
  for (int i = 0; i < nall; i++) {
    record_first[i] = static_cast<int>(total);
    total += static_cast<std::size_t>(record_count[i]) * entry();
    record_count[i] = 0;
  }
  if (total > pool.capacity()) pool.reserve(total + total / 8);
  pool.resize(total);
  each_touching([&](int i, int j, int jj) {
    const double *v = values(i) + jj * nvalue;
    const tagint mark = marked(touched(i)[jj]);
    add(i, mark * tag[j], v, 1.0);
    if (j < nlocal || newton) add(j, mark * tag[i], v, -1.0);
  });
  if (newton) {
    reverse_what = REVERSE_RECORDS;
    comm->reverse_comm_variable(this);
  }

  int local_max = 1;
  for (int i = 0; i < nlocal; i++)
    local_max = std::max(local_max, record_size(i));
  maxexchange = local_max;
}

// Per-atom records -> flat arrays of the new list, looked up by partner tag.
void FixContactHistory::map_to_list()
{
  if (!list) return;
  if (before_mapping) before_mapping();
  const tagint *tag = atom->tag;
  offset.assign(atom->nlocal + 1, 0);
  int total = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    offset[i] = total;
    total += list->numneigh[i];
  }
  touch.assign(total, 0);
  value.assign(static_cast<size_t>(total) * nvalue, 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int count = record_count[i];
    if (count == 0) continue;
    const double *mine = pool.data() + record_first[i];
    const int *jlist = list->firstneigh[i];
    char *t = touched(i);
    double *v = values(i);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const tagint other = tag[jlist[jj] & NEIGHMASK];
      for (int k = 0; k < count; k++) {
        const tagint stored = static_cast<tagint>(ubuf(mine[k * entry()]).i);
        if (stored != other && stored != -other) continue;
        t[jj] = stored < 0 ? 2 : 1;
        std::copy_n(mine + k * entry() + 1, nvalue, v + jj * nvalue);
        break;
      }
    }
  }
  mapped = true;
  check_order = false;
}

int FixContactHistory::pack_record(int i, double *buf) const
{
  buf[0] = static_cast<double>(record_count[i]);
  std::copy_n(pool.data() + record_first[i], static_cast<std::size_t>(record_count[i]) * entry(), buf + 1);
  return record_size(i);
}

// A record arriving with atom i (exchange or restart file), appended to the pool.
int FixContactHistory::unpack_record(int i, const double *buf)
{
  const int count = static_cast<int>(buf[0]);
  std::copy_n(buf + 1, static_cast<std::size_t>(count) * entry(), append_record(i, count));
  return 1 + count * entry();
}

void FixContactHistory::grow_arrays(int nmax)
{
  record_first.reserve(nmax);    // exactly nmax (resize alone may double the capacity)
  record_count.reserve(nmax);
  record_first.resize(nmax, 0);
  record_count.resize(nmax, 0);
}

void FixContactHistory::copy_arrays(int i, int j, int /*delflag*/)
{
  record_first[j] = record_first[i];
  record_count[j] = record_count[i];
}

void FixContactHistory::set_arrays(int i)
{
  record_count[i] = 0;
}

int FixContactHistory::pack_exchange(int i, double *buf)
{
  return pack_record(i, buf);
}

int FixContactHistory::unpack_exchange(int nlocal, double *buf)
{
  return unpack_record(nlocal, buf);
}

int FixContactHistory::pack_restart(int i, double *buf)
{
  const int m = pack_record(i, buf + 1);
  buf[0] = m + 1;
  return m + 1;
}

void FixContactHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++)
    m += static_cast<int>(extra[nlocal][m]);
  unpack_record(nlocal, &extra[nlocal][m + 1]);
}

int FixContactHistory::size_restart(int i)
{
  return 1 + record_size(i);
}

// The largest over all ranks: rank 0 writes it to the file, whose reader sizes every atom's row
// of per-atom fix values by it (a rank's own max let another's longer records overrun the row).
// Called on every rank (Modify::write_restart).
int FixContactHistory::maxsize_restart()
{
  int local_max = 1, global_max = 1;
  for (int i = 0; i < atom->nlocal; i++)
    local_max = std::max(local_max, record_size(i));
  MPI_Allreduce(&local_max, &global_max, 1, MPI_INT, MPI_MAX, world);
  return 1 + global_max;
}

// Ghosts to their owners (newton on): first their record counts (REVERSE_COUNTS, one value per
// atom, added to the owners' so that store_from_list reserves room), then the records, which
// the owners write in that room.
int FixContactHistory::pack_reverse_comm_size(int n, int first)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    m += record_size(i);
  return m;
}

int FixContactHistory::pack_reverse_comm(int n, int first, double *buf)
{
  if (reverse_what == REVERSE_COUNTS) {
    for (int k = 0; k < n; k++)
      buf[k] = record_count[first + k];
    return n;
  }
  int m = 0;
  for (int i = first; i < first + n; i++)
    m += pack_record(i, buf + m);
  return m;
}

void FixContactHistory::unpack_reverse_comm(int n, int *list_, double *buf)
{
  if (reverse_what == REVERSE_COUNTS) {
    for (int k = 0; k < n; k++)
      record_count[list_[k]] += static_cast<int>(buf[k]);
    return;
  }
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int owner = list_[k], count = static_cast<int>(buf[m]);
    const double *in = buf + m + 1;
    for (int e = 0; e < count; e++, in += entry())
      add(owner, static_cast<tagint>(ubuf(in[0]).i), in + 1, 1.0);
    m += 1 + count * entry();
  }
}

// The flat arrays, the pool and the per-atom places in it.
double FixContactHistory::memory_usage()
{
  return (offset.capacity() + record_first.capacity() + record_count.capacity()) * sizeof(int) + touch.capacity() +
         (value.capacity() + pool.capacity()) * sizeof(double);
}
