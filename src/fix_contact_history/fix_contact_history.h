/* -*- c++ -*- ----------------------------------------------------------
   fix LUBRICATED_HISTORY: per-contact history (the tangential spring elongation) of
   pair_style lubricated/springdashpot. Internal: the pair style creates it in init_style.

   Between neighbor-list builds the history lives in flat arrays aligned with the pair's
   half list (touched flag + nvalue doubles per list entry), written by the pair in
   compute(). On every reneighboring step, before atoms migrate (pre_exchange), each
   touching pair is stored with both atoms as (partner tag, values in that atom's frame):
   owned atoms directly, ghost atoms (newton on) through a reverse communication to their
   owners. The per-atom records travel with migrating atoms and go into restart files;
   after the new list is built (post_neighbor) they are looked up again by partner tag.
   The records of all atoms share one pool (an atom's are contiguous: first, count), sized to
   the touching pairs, not one vector per atom.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_CONTACT_HISTORY_H
#define LMP_FIX_CONTACT_HISTORY_H

#include "fix.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace LAMMPS_NS {

class FixContactHistory : public Fix {
 public:
  FixContactHistory(class LAMMPS *, int, char **);
  ~FixContactHistory() override;

  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void min_pre_exchange() override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void min_post_neighbor() override;
  void post_run() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_reverse_comm_size(int, int) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  void set_list(class NeighList *l) { list = l; }
  // Called after each build, before the history is laid onto the new list's entries: the pair
  // style trims its list there (pair_lubricated_springdashpot_list.cpp).
  std::function<void()> before_mapping;
  // History of list entry jj of atom i: touched flag and nvalue doubles, in i's frame.
  char *touched(int i) { return touch.data() + offset[i]; }
  double *values(int i) { return value.data() + offset[i] * nvalue; }
  // The same as flat arrays: entry e = entry(i, jj) has touched_all()[e] and nvalue doubles
  // from values_all() + nvalue e (loops that keep the entries and both pointers).
  int entry(int i, int jj) const { return offset[i] + jj; }
  char *touched_all() { return touch.data(); }
  double *values_all() { return value.data(); }

 protected:
  int nvalue;
  class NeighList *list = nullptr;
  bool mapped = false;    // the flat arrays hold the current history
  // After a run: the atoms' order its list was built for, checked until the next mapping.
  bool check_order = false;
  std::uint64_t order_at_run_end = 0;
  std::uint64_t atom_order() const;
  bool list_still_current();

  // Flat arrays aligned with the half list: entry jj of atom i at offset[i] + jj.
  std::vector<int> offset;
  std::vector<char> touch;
  std::vector<double> value;

  // Per atom (owned and ghost): its partners' records in the pool, each the partner's tag
  // (ubuf, its sign the touched flag: marked) and the values in this atom's frame (entry doubles),
  // from record_first[i] on.
  // Records are never changed in place (copy_arrays may share them): a new one is appended.
  std::vector<double> pool;
  std::vector<int> record_first, record_count;
  int entry() const { return 1 + nvalue; }
  int record_size(int i) const { return 1 + record_count[i] * entry(); }
  enum { REVERSE_COUNTS, REVERSE_RECORDS } reverse_what = REVERSE_RECORDS;

  void store_from_list();
  void map_to_list();
  void add(int i, tagint other, const double *v, double sign);
  // The touched flag travels with a record as the sign of the partner's tag: 1 (tag > 0) or 2
  // (tag < 0; the pair style's contact that has slid, lubricated::history_flag).
  static tagint marked(char flag) { return flag == 2 ? -1 : 1; }
  double *append_record(int i, int count);
  int pack_record(int i, double *buf) const;
  int unpack_record(int i, const double *buf);
};

}    // namespace LAMMPS_NS

#endif
