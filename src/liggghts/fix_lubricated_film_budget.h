// The many-body film budget of `model lubricated` in LIGGGHTS 3.8.0 (doc/model.rst, "Dense
// beds"; the proof is in src/lubricated/film_budget.h): every film of a pair or a wall is
// applied as LIGGGHTS applies any contact force, recorded here with its share a_k of its cap,
// and once every film of the step is known (the pair's in its compute, the walls' in their
// post_force) each atom's load D_i = sum_k a_k gives the scale 1 / max(1, D_i, D_j) of its
// films; the difference is added to the forces before the velocities are updated
// (pre_final_integrate; at a run's set-up, in setup(), after the walls' own setup).
//
// The pair style's model creates this fix (ID lubricated_film_budget) at its init and keeps
// it after every fix wall/gran, so that all walls have recorded their films before it acts.
// Its arrays live for one step: nothing is stored per atom between steps or in restart files.
//
// The same fix checks the network of sustained contacts (lubricated/contact_network.h) every
// network_check_interval steps where a contact's load can matter (N_c below about 7): an ERROR
// when a mode of the packing provably grows every step, a WARNING when one is likely.
#pragma once

#include "fix.h"

#include "lubricated/coefficients.h"
#include "lubricated/lubrication.h"

#include <vector>

namespace lubricated {
namespace liggghts {

class FixLubricatedFilmBudget : public LAMMPS_NS::Fix {
 public:
  static constexpr const char *id_name = "lubricated_film_budget";
  static constexpr const char *style_name = "lubricated/film_budget";

  FixLubricatedFilmBudget(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void pre_final_integrate() override;

  int pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) override;
  void unpack_comm(int n, int first, double *buf) override;
  int pack_reverse_comm(int n, int first, double *buf) override;
  void unpack_reverse_comm(int n, int *list, double *buf) override;

  // Whether films are to be recorded this step (set at this fix's init and at every neighbor
  // list build, see bound_of_atoms()).
  bool active() const { return active_ && films_can_exceed_; }

  // The budget is skipped until the next neighbor list build where no atom's films can exceed
  // it (film_budget.h, film_share_bound): the pair's model adds, at each build, the share bounds
  // of the pairs that can reach the film before the next build to these per-atom sums (zeroed,
  // owned and ghost atoms), then decide_skip() adds the walls' and decides for every rank.
  double *bound_of_atoms();
  void decide_skip();

  // A wall's films by atom type (index: the type), for the bounds (take_part() too). mesh: a
  // sphere may be in the films of several of its triangles at once: no bound.
  void add_wall_films(const std::vector<Lubrication> &by_type, bool mesh)
  {
    pending_walls_.push_back(WallFilms{by_type, mesh});
  }

  // A new step's films: called by the pair's beginPass; a wall's first film opens it too.
  void begin();

  // A film force f (already applied: on i, and -f on j) of share a = |f| t_kick / (m_e |u_n|).
  // j < 0: a wall. With newton off a pair whose j is a ghost is recorded on both ranks.
  void add_film(int i, int j, const double *f, double share)
  {
    if (!open_) begin();
    records_.push_back(Record{i, j, {f[0], f[1], f[2]}});
    load_[i] += share;
    if (j >= 0 && (newton_pair_ || j < nlocal_)) load_[j] += share;
  }

  // The pair's beginPass: a new step's films, and whether the contact network is checked.
  void begin_pass();

  // The network check's data, from the pair's model (its models are rebuilt when dt changes):
  // per type pair (index i * (ntypes + 1) + j) the normal load of a sustained contact, the load
  // that bounds its normal and tangential springs, and the coefficients (for the message).
  void set_network(int ntypes, const std::vector<double> &normal_load, const std::vector<double> &bound_load,
                   const std::vector<Coefficients> &coefficients);
  bool network_due() const { return network_due_; }
  bool network_load_matters(int type_pair) const { return network_bound_[type_pair] > 0.0; }

  // A contact in overlap now and a step ago; masses the contact moves (infinite: held).
  void add_network_contact(int i, int j, int type_pair, const double *n, double m_e, double m_i, double m_j)
  {
    network_.push_back(NetworkContact{i, j, type_pair, {n[0], n[1], n[2]}, m_e, m_i, m_j});
  }

  // Atoms no contact moves (in no integrated group, or in a held one: fix freeze, fix move):
  // their loads limit nothing (their partners count their shares of these films).
  void set_immovable_groups(int integrate_bits, int hold_bits)
  {
    integrate_bits_ = integrate_bits;
    hold_bits_ = hold_bits;
  }

  // Each model lubricated (pair and walls) takes part at every init, before this fix's own
  // init (the pair's model at force init, the walls' in the fix order before this fix); with
  // none left the fix does nothing. limit_pair: the films keep their per-contact caps only.
  void take_part(bool limit_pair)
  {
    participants_++;
    limit_pair_ = limit_pair_ || limit_pair;
  }

  // create: the fix with this ID, placed after every fix wall/gran (created or moved there;
  // only before modify's init, i.e. from the pair's model). Else the fix as it is, or nullptr.
  static FixLubricatedFilmBudget *find(LAMMPS_NS::LAMMPS *lmp, bool create);

 private:
  struct Record {
    int i, j;
    double f[3];
  };
  struct NetworkContact {
    int i, j, type_pair;
    double n[3], m_e, m_i, m_j;
  };
  struct WallFilms {
    std::vector<Lubrication> by_type;
    bool mesh;
  };
  enum class Exchange { load, scale, correction, network_sums };

  void finish();
  void finish_films();
  void check_network();

  bool open_ = false, active_ = false, limit_pair_ = false, films_can_exceed_ = true;
  std::vector<WallFilms> walls_, pending_walls_;
  int participants_ = 0;
  int newton_pair_ = 0, nlocal_ = 0, integrate_bits_ = ~0, hold_bits_ = 0;
  Exchange exchange_ = Exchange::load;
  std::vector<Record> records_;
  std::vector<double> load_, scale_, correction_;

  bool network_on_ = false, network_pending_ = false, network_due_ = false, network_warned_ = false;
  long long network_next_ = 0;
  int ntypes_ = 0;
  std::vector<double> network_load_, network_bound_, network_sums_;
  std::vector<Coefficients> coefficients_;
  std::vector<NetworkContact> network_;
};

}    // namespace liggghts
}    // namespace lubricated
