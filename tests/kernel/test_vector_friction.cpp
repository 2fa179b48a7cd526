// The pair style's vectorised loop of kept frictional pairs (vector_pairs.cpp, friction_contacts):
// for every pair it takes (in sustained contact that touched at the last step, or apart over the
// step) the same forces, torques, spring energy, elongation and touched flag as the whole contact
// of lubricated::contact_forces<true> over a step, to rounding; the pairs it leaves to the general
// loop are exactly the others, untouched. The same for its loop of the pairs it leaves
// (friction_events: contacts that start or end, new ones), given every pair: it takes all but
// those of two immovable atoms and the rare entry or exit whose first Newton step misses the
// tolerance. Random pairs: gaps from 2 % of R in overlap to past the
// film, slips and spins that stick and slide, elongations with a normal part (rotated into the
// tangent plane), dry and wet, fixed eps_al or grid, with and without the shear film, masses or
// inverse masses (an immovable atom too).
#include "pair_lubricated_springdashpot/vector_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace lubricated;
namespace vp = LAMMPS_NS::vector_pairs;

namespace {

// |a - b| within 1e-11 of the scale (rounding: fused multiply-adds, log_inline, the exponential's
// series; the slide's division by |F| amplifies by at most its own few ulps) plus `spread`, what
// the few ulps of r by which the loop's gap r - R_i - R_j may differ change (near contact the
// gap is a small difference of large numbers).
void expect_close(double a, double b, double scale, const char *what, int pair, double spread = 0.0)
{
  ASSERT_LE(std::fabs(a - b), 1e-11 * scale + spread + 1e-300) << what << " pair " << pair << ": " << a << " vs " << b;
}

struct Scene {
  int n = 0;    // atoms 2k, 2k+1 form pair k
  std::vector<double> x, v, omega, radius, rmass, inverse;
  std::vector<int> pair_i, pair_j;
  std::vector<double> touched, delta_x, delta_y, delta_z;
};

Scene draw_scene(std::mt19937_64 &rng, int pairs, double dt)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto around = [&](double scale) { return scale * (2.0 * unit(rng) - 1.0); };
  Scene s;
  s.n = 2 * pairs;
  for (int k = 0; k < pairs; k++) {
    const double ri = 1e-3 * (0.9 + 0.2 * unit(rng)), rj = 1e-3 * (0.9 + 0.2 * unit(rng));
    // Direction, gap (overlap up to 2 % of R, apart up to 15 %; every third pair within 1.5 steps
    // of contact: entries and exits), normal velocity that keeps a contact sustained, ends it or
    // starts one, and slips from creeping to sliding.
    double nx = around(1.0), ny = around(1.0), nz = around(1.0);
    const double norm = std::sqrt(nx * nx + ny * ny + nz * nz);
    nx /= norm, ny /= norm, nz /= norm;
    const double u_n = (unit(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, -5.0 + 4.0 * unit(rng));
    const double far = 1e-3 * (-0.02 + 0.17 * unit(rng) * unit(rng)), near = around(1.5 * std::fabs(u_n) * dt);
    const double gap = k % 3 == 0 ? near : far;
    const double r = ri + rj + gap;
    const double xi[3] = {around(0.01), around(0.01), around(0.01)};
    for (int d = 0; d < 3; d++)
      s.x.push_back(xi[d]);
    s.x.push_back(xi[0] - r * nx), s.x.push_back(xi[1] - r * ny), s.x.push_back(xi[2] - r * nz);
    const double vt[3] = {around(0.05), around(0.05), around(0.05)};
    s.v.push_back(vt[0] + u_n * nx), s.v.push_back(vt[1] + u_n * ny), s.v.push_back(vt[2] + u_n * nz);
    for (int d = 0; d < 3; d++)
      s.v.push_back(0.0);
    for (int d = 0; d < 6; d++)
      s.omega.push_back(around(50.0));
    s.radius.push_back(ri), s.radius.push_back(rj);
    const double mi = 2500.0 * 4.18879 * ri * ri * ri, mj = 2500.0 * 4.18879 * rj * rj * rj;
    s.rmass.push_back(mi), s.rmass.push_back(mj);
    // Every 17th pair has an immovable partner, every 61st two (no force: left to the general loop).
    s.inverse.push_back(k % 61 == 0 ? 0.0 : 1.0 / mi), s.inverse.push_back(k % 17 == 0 ? 0.0 : 1.0 / mj);
    s.pair_i.push_back(2 * k), s.pair_j.push_back(2 * k + 1);
    // The history's flag: 0 apart, 1 stuck throughout, 2 slid at some step (lubricated::history_flag).
    const double draw = unit(rng);
    s.touched.push_back(draw < 0.5 ? 1.0 : draw < 0.8 ? 2.0 : 0.0);
    // An elongation mostly in the tangent plane (sometimes with a larger normal part), up to what
    // makes the contact slide.
    const double length = std::pow(10.0, -9.0 + 4.0 * unit(rng)) * dt / 1e-5;
    const double tilt = unit(rng) < 0.1 ? 0.5 : 1e-3;
    s.delta_x.push_back(length * (around(1.0) + tilt * nx)), s.delta_y.push_back(length * (around(1.0) + tilt * ny));
    s.delta_z.push_back(length * (around(1.0) + tilt * nz));
  }
  return s;
}

void check_model(const Coefficients &c, bool inverse_masses, bool events, unsigned seed, int &done_count,
                 int &left_count)
{
  const double dt = 1.25e-5;
  ContactModel model = make_contact_model(c, Partner::particle, dt);
  std::mt19937_64 rng(seed);
  const int pairs = 256;
  const Scene s = draw_scene(rng, pairs, dt);
  vp::Atoms atoms{
      s.x.data(),    s.v.data(), s.radius.data(), s.rmass.data(), inverse_masses ? s.inverse.data() : nullptr,
      s.omega.data()};
  std::vector<double> out(20 * pairs);
  auto col = [&](int k) { return out.data() + k * pairs; };
  // Column 0 unused (the normal force is the whole force along n).
  const vp::FrictionOut o{col(1),  col(2),  col(3),  col(4),  col(5),  col(6),  col(7),  col(8),  col(9), col(10),
                          col(11), col(12), col(13), col(14), col(15), col(16), col(17), col(18), col(19)};
  const vp::FrictionIn in{s.pair_i.data(),  s.pair_j.data(),  s.touched.data(),
                          s.delta_x.data(), s.delta_y.data(), s.delta_z.data()};
  if (events)
    (inverse_masses ? vp::friction_events_by_inverse : vp::friction_events)(atoms, model, in, pairs, o);
  else
    (inverse_masses ? vp::friction_contacts_by_inverse : vp::friction_contacts)(atoms, model, in, pairs, o);
  for (int k = 0; k < pairs; k++) {
    const int i = s.pair_i[k], j = s.pair_j[k];
    const double delx = s.x[3 * i] - s.x[3 * j], dely = s.x[3 * i + 1] - s.x[3 * j + 1],
                 delz = s.x[3 * i + 2] - s.x[3 * j + 2];
    const double r = std::sqrt(delx * delx + dely * dely + delz * delz), rinv = 1.0 / r;
    ContactPoint p;
    p.film = film_radius_pair(s.radius[i], s.radius[j]);
    p.gap = r - s.radius[i] - s.radius[j];
    p.n = {delx * rinv, dely * rinv, delz * rinv};
    p.dv = {s.v[3 * i] - s.v[3 * j], s.v[3 * i + 1] - s.v[3 * j + 1], s.v[3 * i + 2] - s.v[3 * j + 2]};
    p.u_n = dot(p.dv, p.n);
    p.reduced_mass =
        inverse_masses ? reduced_mass_of_inverses(s.inverse[i], s.inverse[j]) : reduced_mass(s.rmass[i], s.rmass[j]);
    p.omega_i = {s.omega[3 * i], s.omega[3 * i + 1], s.omega[3 * i + 2]};
    p.omega_j = {s.omega[3 * j], s.omega[3 * j + 1], s.omega[3 * j + 2]};
    p.radius_i = s.radius[i], p.radius_j = s.radius[j];
    p.reduced_radius = s.radius[i] * s.radius[j] / (s.radius[i] + s.radius[j]);
    const double g0 = p.gap - p.u_n * dt;
    const bool sustained = in_sustained_contact(model.normal.step, p.gap, g0);
    const bool apart = !contact_possible(p.gap, p.u_n, dt);
    const bool crossing = (p.gap >= 0.0) != (g0 >= 0.0);    // an entry or exit: a root to find
    const bool takes =
        events ? col(19)[k] != 0.0 : ((sustained && s.touched[k] != 0.0) || apart) && p.reduced_mass > 0.0;
    if (events)
      ASSERT_TRUE(takes || p.reduced_mass == 0.0 || crossing) << "pair " << k;
    else
      ASSERT_EQ(col(19)[k] != 0.0, takes) << "pair " << k;
    if (!takes) {    // left to the general loop: nothing applied, the history as it was
      ++left_count;
      for (int q : {0, 1, 3, 4, 5, 6, 7, 8, 9})
        ASSERT_EQ(col(q)[k], 0.0) << q;
      ASSERT_EQ(col(15)[k], s.delta_x[k]);
      ASSERT_EQ(col(18)[k], s.touched[k]);
      continue;
    }
    ++done_count;
    double h[3] = {s.delta_x[k], s.delta_y[k], s.delta_z[k]};
    HistorySlot slot = history_slot(h, s.touched[k], true);
    const ContactForces f = contact_forces<true>(model, p, slot, Evaluation::step);
    // The same with the gap moved by 1e-15 r (4.5 ulps of r) either way: the outputs' spread.
    double hp[3] = {s.delta_x[k], s.delta_y[k], s.delta_z[k]}, hm[3] = {hp[0], hp[1], hp[2]};
    HistorySlot slot_p = history_slot(hp, s.touched[k], true), slot_m = history_slot(hm, s.touched[k], true);
    ContactPoint moved = p;
    moved.gap = p.gap + 1e-15 * r;
    const ContactForces fp = contact_forces<true>(model, moved, slot_p, Evaluation::step);
    moved.gap = p.gap - 1e-15 * r;
    const ContactForces fm = contact_forces<true>(model, moved, slot_m, Evaluation::step);
    auto spread = [](double a, double b) { return std::fabs(a - b); };
    // Scales: the largest force of the pair (for the contact-event loop also the terms of the
    // normal contact's (g2 - 2 g1 + g0) / dt^2, to whose rounding the event is exact), the
    // elongation's length.
    const double g2 = f.normal.contact / p.reduced_mass * dt * dt + 2.0 * p.gap - g0;
    const double terms =
        events ? p.reduced_mass * (std::fabs(g0) + 2.0 * std::fabs(p.gap) + std::fabs(g2)) / (dt * dt) : 0.0;
    const double force_scale = std::max({std::fabs(f.normal.total()), std::fabs(f.normal.contact),
                                         std::sqrt(dot(f.tangential, f.tangential)), terms, 1e-300});
    const double length_scale = std::max(
        {std::sqrt(dot(Vec3{h[0], h[1], h[2]}, Vec3{h[0], h[1], h[2]})),
         std::sqrt(s.delta_x[k] * s.delta_x[k] + s.delta_y[k] * s.delta_y[k] + s.delta_z[k] * s.delta_z[k]), 1e-300});
    // The film apart is a difference of the film integral at two gaps: its rounding is relative to
    // the integral's size (test_vector_forms.cpp), here up to 1e-10 of the force.
    // The normal force: the whole force along n (friction and shear film are tangential).
    const double along = col(4)[k] * p.n.x + col(5)[k] * p.n.y + col(6)[k] * p.n.z;
    expect_close(along, f.normal.total(), 1e2 * force_scale, "normal force", k,
                 spread(fp.normal.total(), fm.normal.total()));
    expect_close(col(1)[k], f.normal.lubrication, 1e2 * force_scale, "film", k,
                 spread(fp.normal.lubrication, fm.normal.lubrication));
    expect_close(col(3)[k], f.normal.energy, std::fabs(f.normal.energy), "energy", k,
                 spread(fp.normal.energy, fm.normal.energy));
    // The whole force on i: the normal force along n and the tangential force.
    auto whole = [&](const ContactForces &forces) {
      return Vec3{forces.normal.total() * p.n.x + forces.tangential.x,
                  forces.normal.total() * p.n.y + forces.tangential.y,
                  forces.normal.total() * p.n.z + forces.tangential.z};
    };
    const Vec3 w = whole(f), wp = whole(fp), wm = whole(fm);
    expect_close(col(4)[k], w.x, 1e2 * force_scale, "force x", k, spread(wp.x, wm.x));
    expect_close(col(5)[k], w.y, 1e2 * force_scale, "force y", k, spread(wp.y, wm.y));
    expect_close(col(6)[k], w.z, 1e2 * force_scale, "force z", k, spread(wp.z, wm.z));
    expect_close(col(7)[k] * s.radius[i], f.torque_i.x, force_scale * s.radius[i], "torque x", k,
                 spread(fp.torque_i.x, fm.torque_i.x));
    expect_close(col(9)[k] * s.radius[j], f.torque_j.z, force_scale * s.radius[j], "torque j z", k,
                 spread(fp.torque_j.z, fm.torque_j.z));
    expect_close(col(10)[k], f.shear.x, force_scale, "shear film x", k, spread(fp.shear.x, fm.shear.x));
    expect_close(col(15)[k], h[0], length_scale, "elongation x", k, spread(hp[0], hm[0]));
    expect_close(col(16)[k], h[1], length_scale, "elongation y", k, spread(hp[1], hm[1]));
    expect_close(col(17)[k], h[2], length_scale, "elongation z", k, spread(hp[2], hm[2]));
    ASSERT_EQ(col(18)[k], history_flag(slot)) << "pair " << k;
  }
}

}    // namespace

TEST(VectorFriction, EqualsTheWholeContactWhereItApplies)
{
  int done = 0, left = 0;
  unsigned seed = 1;
  for (const char *film : {"dry", "activation", "grid", "activation shearfilm no", "grid shearfilm no"})
    for (bool inverse_masses : {false, true})
      for (int repeat = 0; repeat < 16; repeat++) {
        Coefficients c;
        c.e_dry = 0.9;
        c.friction = repeat % 2 ? 0.3 : 0.05;    // sticking and sliding
        const bool events = repeat >= 8;         // the loop of the pairs the first one leaves
        const std::string kind = film;
        if (kind != "dry") {
          c.viscosity = repeat % 8 < 4 ? 1e-3 : 0.3;
          if (kind.rfind("grid", 0) == 0)
            c.grid_spacing = 1.25e-4;
          else
            c.eps_activation = 0.1;
          if (kind.find("shearfilm no") != std::string::npos) c.shearfilm = 0;
        }
        check_model(c, inverse_masses, events, seed++, done, left);
      }
  // Both kinds are drawn: pairs it takes (sustained or apart) and pairs it leaves.
  EXPECT_GT(done, 5000);
  EXPECT_GT(left, 1000);
}

// film_shear_only (vector_pairs.h): for pairs apart over the step, the whole contact of
// lubricated::contact_forces<true> (normal film along n, shear film at the contact points, no
// friction apart): force on i, torques per unit radius, the shear film alone, the budget's inputs
// (film, capacity m_e |u_n|, slip squared, tangential mass); without records the same force and
// torque to the bit, the budget's inputs left unwritten.
TEST(VectorFriction, FilmShearOnlyIsTheWholeContactApart)
{
  const double dt = 1.25e-5;
  int checked = 0, sheared = 0;    // pairs, and those with a shear film
  unsigned seed = 100;
  for (const char *film : {"activation", "grid"})
    for (bool inverse_masses : {false, true})
      for (double viscosity : {1e-3, 0.3}) {
        Coefficients c;
        c.e_dry = 0.9;
        c.friction = 0.3;
        c.viscosity = viscosity;
        if (std::string(film) == "grid")
          c.grid_spacing = 1.25e-4;
        else
          c.eps_activation = 0.1;
        const ContactModel model = make_contact_model(c, Partner::particle, dt);
        std::mt19937_64 rng(seed++);
        const Scene s = draw_scene(rng, 256, dt);
        // The pairs apart over the step whose atoms move (what the pair style gives this loop).
        std::vector<int> pair_i, pair_j;
        for (std::size_t k = 0; k < s.pair_i.size(); k++) {
          const int i = s.pair_i[k], j = s.pair_j[k];
          double del[3], dv[3];
          for (int d = 0; d < 3; d++)
            del[d] = s.x[3 * i + d] - s.x[3 * j + d], dv[d] = s.v[3 * i + d] - s.v[3 * j + d];
          const double r = std::sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
          const double u_n = (dv[0] * del[0] + dv[1] * del[1] + dv[2] * del[2]) / r;
          const double m_e = inverse_masses ? reduced_mass_of_inverses(s.inverse[i], s.inverse[j])
                                            : reduced_mass(s.rmass[i], s.rmass[j]);
          if (!contact_possible(r - s.radius[i] - s.radius[j], u_n, dt) && m_e > 0.0)
            pair_i.push_back(i), pair_j.push_back(j);
        }
        const int n = static_cast<int>(pair_i.size());
        ASSERT_GT(n, 100);
        const vp::Atoms atoms{
            s.x.data(),    s.v.data(), s.radius.data(), s.rmass.data(), inverse_masses ? s.inverse.data() : nullptr,
            s.omega.data()};
        std::vector<double> out(13 * n, -7.0), bare(13 * n, -7.0);
        auto columns = [n](std::vector<double> &o) {
          auto col = [&o, n](int k) { return o.data() + k * n; };
          return vp::ShearOut{col(2), col(3), col(4),  col(5),  col(6), col(7),
                              col(8), col(9), col(10), col(11), col(12)};
        };
        auto film_shear_only = inverse_masses ? vp::film_shear_only_by_inverse : vp::film_shear_only;
        film_shear_only(atoms, model, pair_i.data(), pair_j.data(), n, out.data(), out.data() + n, columns(out), true);
        film_shear_only(atoms, model, pair_i.data(), pair_j.data(), n, bare.data(), bare.data() + n, columns(bare),
                        false);
        auto at = [n](const std::vector<double> &o, int column, int k) { return o[column * n + k]; };
        for (int k = 0; k < n; k++) {
          const int i = pair_i[k], j = pair_j[k];
          ContactPoint p;
          const Vec3 del{s.x[3 * i] - s.x[3 * j], s.x[3 * i + 1] - s.x[3 * j + 1], s.x[3 * i + 2] - s.x[3 * j + 2]};
          const double r = std::sqrt(dot(del, del));
          p.n = {del.x / r, del.y / r, del.z / r};
          p.film = film_radius_pair(s.radius[i], s.radius[j]);
          p.gap = r - s.radius[i] - s.radius[j];
          p.dv = {s.v[3 * i] - s.v[3 * j], s.v[3 * i + 1] - s.v[3 * j + 1], s.v[3 * i + 2] - s.v[3 * j + 2]};
          p.u_n = dot(p.dv, p.n);
          p.reduced_mass = inverse_masses ? reduced_mass_of_inverses(s.inverse[i], s.inverse[j])
                                          : reduced_mass(s.rmass[i], s.rmass[j]);
          p.omega_i = {s.omega[3 * i], s.omega[3 * i + 1], s.omega[3 * i + 2]};
          p.omega_j = {s.omega[3 * j], s.omega[3 * j + 1], s.omega[3 * j + 2]};
          p.radius_i = s.radius[i], p.radius_j = s.radius[j];
          p.reduced_radius = s.radius[i] * s.radius[j] / (s.radius[i] + s.radius[j]);
          HistorySlot none;    // apart: no elongation acts
          const ContactForces f = contact_forces<true>(model, p, none, Evaluation::step);
          const Vec3 whole{f.normal.total() * p.n.x + f.tangential.x, f.normal.total() * p.n.y + f.tangential.y,
                           f.normal.total() * p.n.z + f.tangential.z};
          const double scale =
              std::max({std::fabs(f.normal.total()), std::sqrt(dot(f.tangential, f.tangential)), 1e-300});
          // The film apart's rounding is relative to the film integral (test_vector_forms.cpp).
          expect_close(at(out, 0, k), f.normal.lubrication, 1e2 * scale, "film", k);
          expect_close(at(out, 1, k), p.reduced_mass * std::fabs(p.u_n), p.reduced_mass * std::fabs(p.u_n), "capacity",
                       k);
          expect_close(at(out, 2, k), whole.x, 1e2 * scale, "force x", k);
          expect_close(at(out, 3, k), whole.y, 1e2 * scale, "force y", k);
          expect_close(at(out, 4, k), whole.z, 1e2 * scale, "force z", k);
          expect_close(at(out, 5, k), f.shear.x, scale, "shear film x", k);
          expect_close(at(out, 7, k), f.shear.z, scale, "shear film z", k);
          expect_close(at(out, 8, k) * s.radius[i], f.torque_i.x, scale * s.radius[i], "torque i x", k);
          expect_close(at(out, 10, k) * s.radius[j], f.torque_j.z, scale * s.radius[j], "torque j z", k);
          expect_close(at(out, 11, k), dot(f.slip, f.slip), dot(f.slip, f.slip), "slip squared", k);
          expect_close(at(out, 12, k), tangential_mass_ratio * p.reduced_mass, p.reduced_mass, "tangential mass", k);
          for (int column : {2, 3, 4, 8, 9, 10})
            ASSERT_EQ(at(bare, column, k), at(out, column, k)) << "column " << column << " pair " << k;
          for (int column : {0, 1, 5, 6, 7, 11, 12})
            ASSERT_EQ(at(bare, column, k), -7.0) << "column " << column << " pair " << k;
          checked++;
          sheared += dot(f.shear, f.shear) > 0.0;
        }
      }
  EXPECT_GT(checked, 800);
  EXPECT_GT(sheared, 300);
}
