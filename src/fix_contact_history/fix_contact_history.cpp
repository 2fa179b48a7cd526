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
// Between runs (write_restart, write_data, a changed group) the per-atom records are the truth:
// they migrate with the atoms that write_restart, write_data or the next set-up move and
// reorder, while the list and its flat arrays go stale; so nothing is stored from them again
// until the next set-up has mapped the records onto its new list.
void FixContactHistory::post_run()
{
  store_from_list();
  mapped = false;
}

void FixContactHistory::add(int i, tagint other, const double *v, double sign)
{
  partner[i].push_back(other);
  for (int k = 0; k < nvalue; k++)
    partner_value[i].push_back(sign * v[k]);
}

// Flat list arrays -> per-atom records of both atoms of every touching pair.
void FixContactHistory::store_from_list()
{
  if (!mapped || !list) return;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const bool newton = force->newton_pair != 0;
  for (int i = 0; i < nall; i++) {
    partner[i].clear();
    partner_value[i].clear();
  }
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    const char *t = touched(i);
    const double *v = values(i);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      if (!t[jj]) continue;
      const int j = jlist[jj] & NEIGHMASK;
      add(i, tag[j], v + jj * nvalue, 1.0);
      // With newton off a ghost partner's own rank holds the pair too and stores it there.
      if (j < nlocal || newton) add(j, tag[i], v + jj * nvalue, -1.0);
    }
  }
  if (newton) comm->reverse_comm_variable(this);

  int local_max = 1;
  for (int i = 0; i < nlocal; i++)
    local_max = std::max(local_max, record_size(i));
  maxexchange = local_max;
}

// Per-atom records -> flat arrays of the new list, looked up by partner tag.
void FixContactHistory::map_to_list()
{
  if (!list) return;
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
    const std::vector<tagint> &mine = partner[i];
    if (mine.empty()) continue;
    const int *jlist = list->firstneigh[i];
    char *t = touched(i);
    double *v = values(i);
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const tagint other = tag[jlist[jj] & NEIGHMASK];
      for (size_t k = 0; k < mine.size(); k++) {
        if (mine[k] != other) continue;
        t[jj] = 1;
        std::copy_n(partner_value[i].data() + k * nvalue, nvalue, v + jj * nvalue);
        break;
      }
    }
  }
  mapped = true;
}

int FixContactHistory::pack_record(int i, double *buf) const
{
  int m = 0;
  buf[m++] = static_cast<double>(partner[i].size());
  for (size_t k = 0; k < partner[i].size(); k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    for (int d = 0; d < nvalue; d++)
      buf[m++] = partner_value[i][k * nvalue + d];
  }
  return m;
}

int FixContactHistory::unpack_record(int i, const double *buf, bool append)
{
  if (!append) {
    partner[i].clear();
    partner_value[i].clear();
  }
  int m = 0;
  const int n = static_cast<int>(buf[m++]);
  for (int k = 0; k < n; k++) {
    partner[i].push_back(static_cast<tagint>(ubuf(buf[m++]).i));
    for (int d = 0; d < nvalue; d++)
      partner_value[i].push_back(buf[m++]);
  }
  return m;
}

void FixContactHistory::grow_arrays(int nmax)
{
  partner.resize(nmax);
  partner_value.resize(nmax);
}

void FixContactHistory::copy_arrays(int i, int j, int /*delflag*/)
{
  partner[j] = partner[i];
  partner_value[j] = partner_value[i];
}

void FixContactHistory::set_arrays(int i)
{
  partner[i].clear();
  partner_value[i].clear();
}

int FixContactHistory::pack_exchange(int i, double *buf)
{
  return pack_record(i, buf);
}

int FixContactHistory::unpack_exchange(int nlocal, double *buf)
{
  return unpack_record(nlocal, buf, false);
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
  unpack_record(nlocal, &extra[nlocal][m + 1], false);
}

int FixContactHistory::size_restart(int i)
{
  return 1 + record_size(i);
}

int FixContactHistory::maxsize_restart()
{
  int local_max = 1;
  for (int i = 0; i < atom->nlocal; i++)
    local_max = std::max(local_max, record_size(i));
  return 1 + local_max;
}

// Ghost records (newton on) go to their owners, which append them.
int FixContactHistory::pack_reverse_comm_size(int n, int first)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    m += record_size(i);
  return m;
}

int FixContactHistory::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    m += pack_record(i, buf + m);
  return m;
}

void FixContactHistory::unpack_reverse_comm(int n, int *list_, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    m += unpack_record(list_[k], buf + m, true);
}

// The flat arrays, and per atom its two record vectors (their headers and contents).
double FixContactHistory::memory_usage()
{
  double bytes = offset.capacity() * sizeof(int) + touch.capacity() + value.capacity() * sizeof(double) +
                 partner.capacity() * sizeof(partner[0]) + partner_value.capacity() * sizeof(partner_value[0]);
  for (size_t i = 0; i < partner.size(); i++)
    bytes += partner[i].capacity() * sizeof(tagint) + partner_value[i].capacity() * sizeof(double);
  return bytes;
}
