// Coupled, implicit film solve (doc/film_solve.rst): the backward-Euler step of all lubrication
// films together, for dense suspensions where the per-atom film budget (film_budget.h) would scale
// the films down.
//
// Unknowns: per atom the translational and angular velocity w = (v, omega), 6 values per atom,
// atoms 0..owned-1 owned and owned..total-1 ghosts (copies of atoms owned elsewhere, or periodic
// images). Each film k is a linear damper of the step: the normal film -c_n u_n n on i with
// u_n = n . (v_i - v_j) (lubrication.h, c_n = Lubrication::damping), the shear film -c_t s on i
// with the slip s of tangential.h, and the opposite force on j with the torques of tangential.h,
// and the rolling film's torque -gamma P_t (omega_i - omega_j) on i, the opposite on j.
// Their resistance R (the generalised force of all films is -R w) is symmetric positive
// semi-definite. The step solves
//   (M + dt R) w' = M w + dt (F + f_wall)
// for the increment x = w' - w, (M + dt R) x = dt (F + f(w)), with f(w) the films' force at the
// velocities of the step (including moving walls and the ghosts' velocities as the engine keeps
// them, e.g. with a deforming box's velocity remap: the increment is the same for an atom and
// its images). Dividing by M makes the operator A = I + dt M^-1 R self-adjoint in the mass inner
// product <x, y>_M = sum m x_v . y_v + I x_omega . y_omega, with eigenvalues >= 1; conjugate
// gradients run in that inner product (atoms of inverse mass or inertia 0 keep those components
// at 0 and weigh nothing). Converged when |r|_M <= tolerance |b|_M, b = dt M^-1 (F + f(w)) the
// explicit kick: the kinetic energy of the error of w' is then at most tolerance^2 times the
// kinetic energy of the explicit kick (A >= I).
//
// Preconditioner: per atom the 6x6 block of A (the atom's own films and drag, translation and
// rotation coupled by the shear film), inverted once per solve. Exact for an atom whose partners
// do not move; the identity for an atom without films.
//
// Parallel use: each film must appear on exactly one process (Newton's third law across
// processes: films with a ghost partner are summed back to its owner by the reverse callback).
// The callbacks see per-atom vectors of 6 values (forward and reverse, every iteration) and of
// 36 (reverse, once per solve: the preconditioner's blocks), and sums of at most 3 values.
//
// Use: pack w = (v, omega) and F = (force, torque) per atom (stride 6), fill FilmLink per film
// and FilmAtoms, call FilmSolver::solve (keep the solver: it reuses its buffers), add the
// increment to the velocities, and report FilmSolveResult (iterations, residual, converged).
// film_link_force at w' gives each film's force of the step (virial, stress).
#pragma once

#include "lubricated/tangential.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace lubricated {

constexpr int film_dofs = 6;    // per atom: v (3), omega (3)

// One film: a pair i-j (j >= 0) or a wall at i (j < 0).
struct FilmLink {
  int i = 0, j = -1;
  Vec3 normal;                    // unit normal from j (or the wall) to i
  double normal_damping = 0.0;    // c_n >= 0 [force / velocity]: force -c_n u_n n on i
  double shear_damping = 0.0;     // c_t >= 0 [force / velocity]: force -c_t s on i (raw, not exp-integrated)
  double roll_damping = 0.0;      // gamma >= 0 [torque / angular velocity]: the rolling film's
                                  // torque -gamma P_t (omega_i - omega_j) on i, the opposite on j
  Vec3 wall_velocity;             // wall only: velocity of the wall surface at the contact
};

// Per-atom data, owned + ghost (index 0..total-1); a zero inverse mass or inertia: immovable.
struct FilmAtoms {
  int owned = 0, total = 0;
  const double *inverse_mass = nullptr;
  const double *inverse_inertia = nullptr;
  const double *radius = nullptr;
  // Optional linear dampers of each owned atom solved implicitly with the films (e.g. a Stokes
  // drag c_d (u_f - v)); the caller includes their force at w in F. nullptr: none.
  const double *drag = nullptr;               // [force / velocity]
  const double *rotational_drag = nullptr;    // [torque / angular velocity]
};

// Communication of a per-atom vector of `per_atom` doubles (stride per_atom). Defaults: one
// process without ghosts.
struct FilmComm {
  std::function<void(double *data, int per_atom)> forward;    // ghosts' entries := their owners'
  std::function<void(double *data, int per_atom)> reverse;    // owners += their ghosts' entries
  std::function<void(double *values, int count)> sum;         // in place, over all processes
};

enum class FilmPreconditioner { mass, block };

struct FilmSolveOptions {
  double tolerance = 1e-8;     // relative residual |r|_M / |b|_M
  int max_iterations = 200;    // conjugate-gradient iterations (matrix-vector products)
  FilmPreconditioner preconditioner = FilmPreconditioner::block;
  // Keep the last solve's preconditioner blocks (the same atoms in the same order; any SPD
  // blocks precondition correctly, older ones less well as the films change) where they were
  // made for this step and cover every atom with a film.
  bool reuse_blocks = false;
  bool warm_start = false;    // start from the increment passed in, scaled at best (else from 0)
};

// The films a step's solve took, for the contact-network check (contact_network.h): its links
// (this process's, also those another process solves).
struct SolvedFilms {
  const FilmLink *links = nullptr;
  int count = 0;
};

struct FilmSolveResult {
  int iterations = 0;       // products with the film operator
  double residual = 0.0;    // final |r|_M / |b|_M (0 when b = 0)
  bool converged = false;
};

// The surfaces' slip of a film (tangential.h): s = P_t (v_i - v_j) - (R_i omega_i + R_j omega_j) x n,
// with v_j, omega_j, R_j = 0 for a wall (its velocity already in dv).
inline Vec3 film_surface_slip(const Vec3 &n, const Vec3 &dv, double radius_i, const Vec3 &omega_i, double radius_j,
                              const Vec3 &omega_j)
{
  return minus(tangential_part(dv, n), cross(plus(scaled(omega_i, radius_i), scaled(omega_j, radius_j)), n));
}

// A film's force on i, and its torques on i and j, at the velocities w (6 per atom); with_wall:
// count the wall's velocity (the affine part), else the linear part only.
struct FilmLinkForce {
  Vec3 force_i, torque_i, torque_j;    // force on j: -force_i
};
inline Vec3 film_vec(const double *w)
{
  return {w[0], w[1], w[2]};
}
inline FilmLinkForce film_link_force(const FilmLink &k, const FilmAtoms &atoms, const double *w, bool with_wall)
{
  const double *wi = w + film_dofs * k.i;
  const bool wall = k.j < 0;
  const double *wj = wall ? nullptr : w + film_dofs * k.j;
  Vec3 dv = film_vec(wi);
  if (!wall)
    dv = minus(dv, film_vec(wj));
  else if (with_wall)
    dv = minus(dv, k.wall_velocity);
  const double radius_i = atoms.radius[k.i], radius_j = wall ? 0.0 : atoms.radius[k.j];
  const Vec3 omega_j = wall ? Vec3{} : film_vec(wj + 3);
  const Vec3 slip = film_surface_slip(k.normal, dv, radius_i, film_vec(wi + 3), radius_j, omega_j);
  const Vec3 shear = scaled(slip, -k.shear_damping);
  FilmLinkForce f;
  f.force_i = plus(scaled(k.normal, -k.normal_damping * dot(k.normal, dv)), shear);
  // tangential.h: torque on i -R_i n x F_t, on j -R_j n x F_t (the normal force has no torque).
  const Vec3 n_cross_shear = cross(k.normal, shear);
  f.torque_i = scaled(n_cross_shear, -radius_i);
  f.torque_j = scaled(n_cross_shear, -radius_j);
  if (k.roll_damping > 0.0) {
    const Vec3 roll = scaled(tangential_part(minus(film_vec(wi + 3), omega_j), k.normal), -k.roll_damping);
    f.torque_i = plus(f.torque_i, roll);
    f.torque_j = minus(f.torque_j, roll);
  }
  return f;
}

inline void film_add(double *a, const Vec3 &v, double sign)
{
  a[0] += sign * v.x;
  a[1] += sign * v.y;
  a[2] += sign * v.z;
}

// Sum of all films' forces and torques at w into out (6 per atom, owned + ghost; zeroed here).
inline void film_forces(const FilmAtoms &atoms, const FilmLink *links, int n_links, const double *w, bool with_wall,
                        double *out)
{
  std::fill(out, out + film_dofs * atoms.total, 0.0);
  for (int k = 0; k < n_links; k++) {
    const FilmLinkForce f = film_link_force(links[k], atoms, w, with_wall);
    double *oi = out + film_dofs * links[k].i;
    film_add(oi, f.force_i, 1.0);
    film_add(oi + 3, f.torque_i, 1.0);
    if (links[k].j < 0) continue;
    double *oj = out + film_dofs * links[k].j;
    film_add(oj, f.force_i, -1.0);
    film_add(oj + 3, f.torque_j, 1.0);
  }
}

// Cholesky factorisation in place of an SPD n x n matrix (row-major; lower triangle used).
inline void film_cholesky(double *a, int n)
{
  for (int c = 0; c < n; c++) {
    double d = a[c * n + c];
    for (int k = 0; k < c; k++)
      d -= a[c * n + k] * a[c * n + k];
    a[c * n + c] = std::sqrt(d);
    for (int r = c + 1; r < n; r++) {
      double s = a[r * n + c];
      for (int k = 0; k < c; k++)
        s -= a[r * n + k] * a[c * n + k];
      a[r * n + c] = s / a[c * n + c];
    }
  }
}

// Solves L L^T x = b in place with the factor of film_cholesky.
inline void film_cholesky_solve(const double *l, int n, double *b)
{
  for (int r = 0; r < n; r++) {
    for (int k = 0; k < r; k++)
      b[r] -= l[r * n + k] * b[k];
    b[r] /= l[r * n + r];
  }
  for (int r = n - 1; r >= 0; r--) {
    for (int k = r + 1; k < n; k++)
      b[r] -= l[k * n + r] * b[k];
    b[r] /= l[r * n + r];
  }
}

// Adds one atom's share c B^T B of a film to its 6x6 resistance block: the normal film
// c_n n n^T; the shear film with B = [P_t, sign R N] (N w = n x w; sign +1 on i, the slip's
// rotation term being +R_i n x omega_i, and R_j n x omega_j on j with the translation -P_t):
// c_t [P_t, sign R N; -sign R N, R^2 P_t] (N^T N = P_t, P_t N = N); the rolling film gamma P_t on
// the spin.
inline void film_add_block(double *block, const FilmLink &k, double radius, double side)
{
  const double n[3] = {k.normal.x, k.normal.y, k.normal.z};
  const double cross_n[3][3] = {{0.0, -n[2], n[1]}, {n[2], 0.0, -n[0]}, {-n[1], n[0], 0.0}};
  const double ct = k.shear_damping, rotation = side * radius * ct;
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      const double tangent = (a == b ? 1.0 : 0.0) - n[a] * n[b];
      block[a * 6 + b] += k.normal_damping * n[a] * n[b] + ct * tangent;
      block[(a + 3) * 6 + b + 3] += (ct * radius * radius + k.roll_damping) * tangent;
      block[a * 6 + b + 3] += rotation * cross_n[a][b];
      block[(a + 3) * 6 + b] -= rotation * cross_n[a][b];
    }
}

// The starting guess of a step's increments (warm start) from those of the last steps, solved in
// a row with the atoms in the same order: `depth` of them are known (0, 1 or 2). increment
// holds the last step's x_{n-1} (n values) and becomes the guess: 2 x_{n-1} - x_{n-2} (depth 2:
// the increments change smoothly along a trajectory), x_{n-1} (depth 1) or 0; previous holds
// x_{n-2} (depth 2) and becomes x_{n-1}. Returns whether there is a guess.
inline bool film_increment_guess(double *increment, double *previous, int n, int depth)
{
  if (depth <= 0) return false;
  for (int e = 0; e < n; e++) {
    const double last = increment[e];
    if (depth >= 2) increment[e] = 2.0 * last - previous[e];
    previous[e] = last;
  }
  return true;
}

class FilmSolver {
 public:
  // Solves for the increment x = w' - w (6 per atom, owned + ghost; forward-communicated at the
  // end). velocity: w, owned + ghost, as the engine has them; force: F (force, torque), owned.
  FilmSolveResult solve(const FilmAtoms &atoms, const FilmLink *links, int n_links, double dt, const double *velocity,
                        const double *force, double *increment, const FilmSolveOptions &options,
                        const FilmComm &comm = {});

 private:
  const FilmAtoms *atoms_ = nullptr;
  const FilmLink *links_ = nullptr;
  int n_links_ = 0;
  double dt_ = 0.0;
  const FilmComm *comm_ = nullptr;
  std::vector<double> weight_, inverse_, drag_, residual_, preconditioned_, direction_, product_, accumulated_, blocks_;
  std::vector<char> has_block_;

  void forward(double *data, int per_atom) const
  {
    if (comm_->forward) comm_->forward(data, per_atom);
  }
  void reverse(double *data, int per_atom) const
  {
    if (comm_->reverse) comm_->reverse(data, per_atom);
  }
  void sum(double *values, int count) const
  {
    if (comm_->sum) comm_->sum(values, count);
  }
  double inverse_of(int atom, int d) const
  {
    return d < 3 ? atoms_->inverse_mass[atom] : atoms_->inverse_inertia[atom];
  }
  double drag_of(int atom, int d) const
  {
    const double *c = d < 3 ? atoms_->drag : atoms_->rotational_drag;
    return c ? c[atom] : 0.0;
  }
  // <x, y>_M over owned atoms, this process's part.
  double local_dot(const double *x, const double *y) const
  {
    double s = 0.0;
    for (int e = 0; e < film_dofs * atoms_->owned; e++)
      s += weight_[e] * x[e] * y[e];
    return s;
  }
  void setup_weights();    // weight_ (masses), inverse_, drag_ per component of the owned atoms
  void setup_blocks(bool use_blocks);
  double blocks_dt_ = 0.0;    // the step the blocks were made for
  bool blocks_cover_links() const;
  bool blocks_cover_links_everywhere() const
  {
    double missing = blocks_cover_links() ? 0.0 : 1.0;
    sum(&missing, 1);    // every process makes its blocks again, or none: their set-up communicates
    return missing == 0.0;
  }
  void apply(double *p, double *q);
  void precondition(const double *r, double *z) const;
};

inline void FilmSolver::setup_weights()
{
  const int n = film_dofs * atoms_->owned;
  weight_.resize(n), inverse_.resize(n), drag_.resize(n);
  for (int i = 0; i < atoms_->owned; i++)
    for (int d = 0; d < film_dofs; d++) {
      const int e = film_dofs * i + d;
      inverse_[e] = inverse_of(i, d);
      drag_[e] = drag_of(i, d);
      weight_[e] = inverse_[e] > 0.0 ? 1.0 / inverse_[e] : 0.0;
    }
}

// The block B_i = (I + dt M_i^-1 R_ii)^-1 = I - S G^-1 dt S R_ii with S = M_i^-1/2 and the SPD
// G = I + dt S R_ii S (push-through identity; valid for immovable components, S = 0 there).
// M B_i = M (M + dt R_ii)^-1 M is symmetric positive: B is a valid preconditioner in <,>_M.
inline void FilmSolver::setup_blocks(bool use_blocks)
{
  const int owned = atoms_->owned, total = atoms_->total;
  has_block_.assign(owned, 0);
  blocks_dt_ = dt_;
  if (!use_blocks) return;
  accumulated_.assign(36 * total, 0.0);    // R_ii of every atom, then summed to the owners
  for (int k = 0; k < n_links_; k++) {
    const FilmLink &l = links_[k];
    film_add_block(&accumulated_[36 * l.i], l, atoms_->radius[l.i], 1.0);
    if (l.j >= 0) film_add_block(&accumulated_[36 * l.j], l, atoms_->radius[l.j], -1.0);
  }
  reverse(accumulated_.data(), 36);
  blocks_.assign(36 * owned, 0.0);
  for (int i = 0; i < owned; i++) {
    double *r = &accumulated_[36 * i];
    double scale[6];
    bool any = false;
    for (int d = 0; d < 6; d++) {
      r[d * 6 + d] += drag_of(i, d);
      scale[d] = std::sqrt(inverse_of(i, d));
    }
    for (int e = 0; e < 36; e++)
      any |= r[e] != 0.0;
    if (!any) continue;
    has_block_[i] = 1;
    double g[36], c[36];    // G, then dt S R_ii column by column
    for (int a = 0; a < 6; a++)
      for (int b = 0; b < 6; b++)
        g[a * 6 + b] = (a == b ? 1.0 : 0.0) + dt_ * scale[a] * r[a * 6 + b] * scale[b];
    film_cholesky(g, 6);
    double *block = &blocks_[36 * i];
    for (int b = 0; b < 6; b++) {
      double column[6];
      for (int a = 0; a < 6; a++)
        column[a] = dt_ * scale[a] * r[a * 6 + b];
      film_cholesky_solve(g, 6, column);
      for (int a = 0; a < 6; a++)
        c[a * 6 + b] = column[a];
    }
    for (int a = 0; a < 6; a++)
      for (int b = 0; b < 6; b++)
        block[a * 6 + b] = (a == b ? 1.0 : 0.0) - scale[a] * c[a * 6 + b];
  }
}

// Whether the kept blocks can precondition this solve: made for this step and these atoms, and
// every owned atom of a film has one (an atom whose films joined the solve since has none).
inline bool FilmSolver::blocks_cover_links() const
{
  const int owned = atoms_->owned;
  if (static_cast<int>(has_block_.size()) != owned || blocks_dt_ != dt_) return false;
  for (int k = 0; k < n_links_; k++) {
    const FilmLink &l = links_[k];
    if ((l.i < owned && !has_block_[l.i]) || (l.j >= 0 && l.j < owned && !has_block_[l.j])) return false;
  }
  return true;
}

// q = A p = p + dt M^-1 (R p + drag p) on owned atoms; p's ghost entries are filled here.
inline void FilmSolver::apply(double *p, double *q)
{
  forward(p, film_dofs);
  film_forces(*atoms_, links_, n_links_, p, false, accumulated_.data());
  reverse(accumulated_.data(), film_dofs);
  for (int e = 0; e < film_dofs * atoms_->owned; e++)
    q[e] = p[e] + dt_ * inverse_[e] * (drag_[e] * p[e] - accumulated_[e]);
}

inline void FilmSolver::precondition(const double *r, double *z) const
{
  for (int i = 0; i < atoms_->owned; i++) {
    const double *ri = r + film_dofs * i;
    double *zi = z + film_dofs * i;
    if (!has_block_[i]) {
      std::copy(ri, ri + film_dofs, zi);
      continue;
    }
    const double *block = &blocks_[36 * i];
    for (int a = 0; a < 6; a++) {
      double s = 0.0;
      for (int b = 0; b < 6; b++)
        s += block[a * 6 + b] * ri[b];
      zi[a] = s;
    }
  }
}

inline FilmSolveResult FilmSolver::solve(const FilmAtoms &atoms, const FilmLink *links, int n_links, double dt,
                                         const double *velocity, const double *force, double *increment,
                                         const FilmSolveOptions &options, const FilmComm &comm)
{
  atoms_ = &atoms, links_ = links, n_links_ = n_links, dt_ = dt, comm_ = &comm;
  const int n_owned = film_dofs * atoms.owned, n_total = film_dofs * atoms.total;
  setup_weights();
  const bool use_blocks = options.preconditioner == FilmPreconditioner::block;
  if (!(use_blocks && options.reuse_blocks && blocks_cover_links_everywhere())) setup_blocks(use_blocks);
  for (auto *v : {&residual_, &preconditioned_, &direction_, &product_, &accumulated_})
    v->assign(n_total, 0.0);

  // b = dt M^-1 (F + f(w)): the explicit kick, with the films' force at the step's velocities.
  film_forces(atoms, links, n_links, velocity, true, accumulated_.data());
  reverse(accumulated_.data(), film_dofs);
  for (int e = 0; e < n_owned; e++)
    residual_[e] = dt * (force[e] + accumulated_[e]) * inverse_[e];
  double norms[2] = {local_dot(residual_.data(), residual_.data()), 0.0};
  if (options.warm_start) {
    // The guess g scaled by the alpha that minimises the error's A-norm along it, <g, b> / <g, Ag>
    // (mass products): never a worse start than 0, whatever the guess.
    std::copy(increment, increment + n_owned, direction_.begin());
    apply(direction_.data(), product_.data());
    double along[2] = {local_dot(direction_.data(), residual_.data()), local_dot(direction_.data(), product_.data())};
    sum(along, 2);
    const double alpha = along[1] > 0.0 ? along[0] / along[1] : 0.0;
    for (int e = 0; e < n_owned; e++) {
      increment[e] = alpha * direction_[e];
      residual_[e] -= alpha * product_[e];
    }
  } else {
    std::fill(increment, increment + n_total, 0.0);
  }
  precondition(residual_.data(), preconditioned_.data());
  norms[1] = local_dot(residual_.data(), residual_.data());
  double rho = local_dot(residual_.data(), preconditioned_.data());
  double reduced[3] = {norms[0], norms[1], rho};
  sum(reduced, 3);
  const double kick_sq = reduced[0];
  double residual_sq = reduced[1];
  rho = reduced[2];
  FilmSolveResult result;
  const double target_sq = options.tolerance * options.tolerance * kick_sq;
  result.converged = residual_sq <= target_sq;
  std::copy(preconditioned_.begin(), preconditioned_.begin() + n_owned, direction_.begin());
  while (!result.converged && result.iterations < options.max_iterations) {
    apply(direction_.data(), product_.data());
    double curvature = local_dot(direction_.data(), product_.data());
    sum(&curvature, 1);
    if (!(curvature > 0.0)) break;    // A >= I: only a non-finite input gets here
    const double alpha = rho / curvature;
    for (int e = 0; e < n_owned; e++) {
      increment[e] += alpha * direction_[e];
      residual_[e] -= alpha * product_[e];
    }
    result.iterations++;
    precondition(residual_.data(), preconditioned_.data());
    double next[2] = {local_dot(residual_.data(), residual_.data()),
                      local_dot(residual_.data(), preconditioned_.data())};
    sum(next, 2);
    residual_sq = next[0];
    result.converged = residual_sq <= target_sq;
    const double beta = next[1] / rho;
    rho = next[1];
    for (int e = 0; e < n_owned; e++)
      direction_[e] = preconditioned_[e] + beta * direction_[e];
  }
  result.residual = kick_sq > 0.0 ? std::sqrt(residual_sq / kick_sq) : 0.0;
  forward(increment, film_dofs);
  return result;
}

}    // namespace lubricated
