// Noise over four dimensions, p and a fourth coordinate w (usually time),
// for animations that evolve rather than slide: the 1989 gradient noise
// (section 2.3) over a 4D lattice, and turbulence and periodic forms of it.
#pragma once

#include "nodes/semantics/noise.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

// Visits the 2^4 knots around (p, w) a row along x at a time, as
// for_each_noise_row does in 3D: slots (i + phi(j + phi(k + phi(l)))) mod n,
// the 1989 hash with one more fold, and offsets (u[i], v, s, t) =
// (p, w) - (i, j, k, l).
template <class F, class Axis, class Visit>
void for_each_noise4_row(const NoiseTables& tables, F x, F y, F z, F w, const Axis& ax, const Axis& ay,
                         const Axis& az, const Axis& aw, Visit visit) {
  F fw = w - aw.corner();
  const auto hash_l = entries_at_cells(tables.permutation.data(), aw, IntOf<F>{} + 0);  // phi(l)
  each_of_0_and_1([&](auto dl) {  // written out, as the 3D knots are
    F t = fw - float(dl);
    for_each_noise_row(tables, x, y, z, ax, ay, az, hash_l[dl],
                       [&](const auto& row, const std::array<F, 2>& u, F v, F s) { visit(row, u, v, s, t); });
  });
}

// The same knots one at a time: visit(slot, u, v, s, t).
template <class F, class Axis, class Visit>
void for_each_noise4_knot(const NoiseTables& tables, F x, F y, F z, F w, const Axis& ax, const Axis& ay,
                          const Axis& az, const Axis& aw, Visit visit) {
  for_each_noise4_row(tables, x, y, z, w, ax, ay, az, aw,
                      [&](const auto& row, const std::array<F, 2>& u, F v, F s, F t) {
                        each_of_0_and_1([&](auto di) { visit(row.slot(di), u[di], v, s, t); });
                      });
}

// A knot's 4D gradient: the unit vector G[phi(slot)] of the 3D tables for
// (x, y, z), and for w the x component of G[slot], another table entry. A
// coordinate of a uniform unit 3-vector is uniform in [-1, 1] (Archimedes),
// so every component has mean 0 and variance 1/3 and they are uncorrelated:
// E[g g^T] = I / 3 in 4D, as for the 3D gradients. Noise is linear in
// independent gradients, so its covariance, hence its spectrum, depends on
// them only through E[g g^T]: it is isotropic in (p, w) to second order.
inline std::array<const float*, 4> noise4_gradient_tables(const NoiseTables& tables) {
  return {tables.hashed_gradient_x.data(), tables.hashed_gradient_y.data(), tables.hashed_gradient_z.data(),
          tables.gradient_x.data()};
}

// g . (u, v, s, t) for a knot's gradient g.
template <class G, class F>
F noise4_slope(const std::array<G, 4>& g, F u, F v, F s, F t) {
  return g[0] * u + g[1] * v + g[2] * s + g[3] * t;
}

// Whether lanes of index type I look up the 4D gradients of a cell's
// eight rows of knots in one go (gather256_knot_rows4, which only
// nodes/lane_vector.h declares).
template <class I, class = void>
struct LooksUpKnotRows4 : std::false_type {};
template <class I>
struct LooksUpKnotRows4<I, std::void_t<decltype(gather256_knot_rows4(std::declval<const NoiseTables&>(),
                                                                     std::declval<I>(), std::declval<I>(),
                                                                     std::declval<I>(), std::declval<I>()))>>
    : std::true_type {};

// The rows of for_each_noise4_row with their knots' 4D gradients:
// visit(g, u, v, s, t), g[axis][knot] for axes x, y, z, w. Lanes that can
// look up all eight rows in one go do, as for_each_noise_gradient_row
// does in 3D.
template <class F, class Axis, class Visit>
void for_each_noise4_gradient_row(const NoiseTables& tables, F x, F y, F z, F w, const Axis& ax, const Axis& ay,
                                  const Axis& az, const Axis& aw, Visit visit) {
  if constexpr (LooksUpKnotRows4<IntOf<F>>::value) {
    const auto rows = [&] {
      if constexpr (Axis::next_cell_hashes_next)
        return gather256_knot_rows4(tables, ax.index(0), ay.index(0), az.index(0), aw.index(0));
      else
        return gather256_knot_rows4(tables, cell_indices(ax), cell_indices(ay), cell_indices(az), cell_indices(aw));
    }();
    F fw = w - aw.corner();
    each_of_0_and_1([&](auto dl) {
      F t = fw - float(dl);
      for_each_row_offset(x, y, z, ax, ay, az, [&](auto dk, auto dj, const std::array<F, 2>& u, F v, F s) {
        visit(rows[4 * dl + 2 * dk + dj], u, v, s, t);
      });
    });
  } else {
    const float* gradient_w = noise4_gradient_tables(tables)[3];
    for_each_noise4_row(tables, x, y, z, w, ax, ay, az, aw,
                        [&](const auto& row, const std::array<F, 2>& u, F v, F s, F t) {
                          const auto [gx, gy, gz] = row.gradients(tables);
                          visit(std::array{gx, gy, gz, row.entries(gradient_w)}, u, v, s, t);
                        });
  }
}

// sum over the 16 knots of w(u) w(v) w(s) w(t) (g . (u, v, s, t)).
template <class F, class Axis>
F noise4_on_axes(const NoiseTables& tables, F x, F y, F z, F w, const Axis& ax, const Axis& ay, const Axis& az,
                 const Axis& aw) {
  F sum = splat<F>(0.0f);
  for_each_noise4_gradient_row(tables, x, y, z, w, ax, ay, az, aw,
                               [&](const auto& g, const std::array<F, 2>& u, F v, F s, F t) {
                                 each_of_0_and_1([&](auto di) {
                                   sum = sum + noise_weight(u[di]) * noise_weight(v) * noise_weight(s) *
                                                   noise_weight(t) *
                                                   noise4_slope(std::array{g[0][di], g[1][di], g[2][di], g[3][di]},
                                                                u[di], v, s, t);
                                 });
                               });
  return sum;
}

template <class F>
F noise4(const NoiseTables& tables, F x, F y, F z, F w) {
  return noise4_on_axes(tables, x, y, z, w, lattice_axis(x), lattice_axis(y), lattice_axis(z), lattice_axis(w));
}

// noise4 repeating every period along x, y, z and every w_period along w
// (whole cells, 1 to 256): with w = time, a loop of w_period.
template <class F>
F pnoise4(const NoiseTables& tables, F x, F y, F z, F w, F px, F py, F pz, F pw) {
  return noise4_on_axes(tables, x, y, z, w, periodic_axis(x, noise_period(px)), periodic_axis(y, noise_period(py)),
                        periodic_axis(z, noise_period(pz)), periodic_axis(w, noise_period(pw)));
}

// Turbulence over (p, w): octave i is noise4 of 2^i (p, w).
template <class F>
F turbulence4(const NoiseTables& tables, F x, F y, F z, F w, F octaves, F filter_width) {
  return turbulence_of(octaves, filter_width,
                       [&](auto f) { return noise4(tables, x * f, y * f, z * f, w * f); });
}

// turbulence4 repeating every period: octave i is pnoise4 of 2^i (p, w)
// with periods 2^i (period, w_period), so every octave repeats where the
// first does.
template <class F>
F pturbulence4(const NoiseTables& tables, F x, F y, F z, F w, F px, F py, F pz, F pw, F octaves,
               F filter_width) {
  const F period_x = noise_period(px), period_y = noise_period(py), period_z = noise_period(pz),
          period_w = noise_period(pw);
  return turbulence_of(octaves, filter_width, [&](auto f) {
    return noise4_on_axes(tables, x * f, y * f, z * f, w * f, periodic_axis(x * f, period_x * f),
                          periodic_axis(y * f, period_y * f), periodic_axis(z * f, period_z * f),
                          periodic_axis(w * f, period_w * f));
  });
}

}  // namespace shadetree::semantics
