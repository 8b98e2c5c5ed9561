// Interval forms of the lattice functions (noise.h, cellular.h), which
// hash cells in bits and so cannot be instantiated over intervals. They
// are overloads in the namespace of Interval: noise, pnoise,
// turbulence, fbm and their periodic twins reach noise_on_axes, the 4D
// noise4, pnoise4, turbulence4 and pturbulence4 reach noise4_on_axes, and
// cellular and pcellular reach cellular_on_axes, by argument-dependent
// lookup, so those ops need no interval form of their own.
#pragma once

#include <cmath>

#include "nodes/lane_interval.h"
#include "nodes/noise_tables.h"
#include "nodes/semantics/cellular.h"
#include "nodes/semantics/noise.h"
#include "nodes/semantics/noise4.h"

namespace shadetree::lanes {

// The proven range of noise. A knot's term is w(u) w(v) w(w) (g . d) with
// g a unit vector (noise_tables.h) and d its offset, and the weights W_k of
// the 8 knots sum to 1 (w(t) + w(1 - t) = 1), so by Cauchy-Schwarz and
// Jensen |noise| <= sum W_k |d_k| <= sqrt(sum W_k |d_k|^2) = sqrt(3 q),
// where q(t) = w(t) t^2 + w(1 - t) (1 - t)^2 <= 1/4 on [0, 1]
// (tests/interval_program_test.cpp checks q): |noise| <= sqrt(3) / 2.
inline constexpr float noise_bound = 0.8660254f;
// The lane form's rounding: some 40 operations on values below 2.
inline constexpr float lattice_rounding_margin = 1e-4f;
// Boxes over more cells than this are bounded by the proven range alone.
inline constexpr int max_enclosed_noise_cells = 8;
// Boxes whose widths (in cells) add up to more than this are bounded by
// the proven range alone. Cell by cell, the enclosure's width grows about
// as that sum does (widths 0.3, 0.02, 0.02: 0.4; 0.3 each: 1.16) until
// it is the whole range: there it tells next to nothing more, at up to 8
// cells' cost (docs/architecture.md, "How tight").
inline constexpr float max_enclosed_noise_width = 1.5f;
// Beyond this, cells are not enumerated (a float step may exceed a cell).
inline constexpr float max_enclosed_noise_coordinate = 8388608.0f;

// w over t in [lo, hi] (lo and hi of one sign): w decreases in |t| on [0, 1].
inline Interval noise_weight_over(Interval t) {
  const float near = t.lo >= 0.0f ? t.lo : -t.hi, far = t.lo >= 0.0f ? t.hi : -t.lo;
  return {semantics::noise_weight(far), semantics::noise_weight(near)};
}

// [-bound, bound] (with the lane form's rounding) where p is finite, else
// everything: a lattice function of an infinite coordinate is NaN.
inline Interval lattice_range(Interval x, Interval y, Interval z, float bound) {
  if (!is_finite(x) || !is_finite(y) || !is_finite(z)) return everything();
  return {-bound - lattice_rounding_margin, bound + lattice_rounding_margin};
}

inline Interval lattice_range(Interval x, Interval y, Interval z, Interval w, float bound) {
  if (!is_finite(w)) return everything();
  return lattice_range(x, y, z, bound);
}

// A lattice function over a box of D coordinates, cell by cell, within its
// proven range: `over_cell(corner, fraction)` encloses it over the box's
// part of one cell, given as offsets from the cell's corner (exact).
template <int D, class OverCell>
Interval lattice_over_cells(const Interval (&box)[D], Interval range, OverCell over_cell) {
  if (is_everything(range)) return range;
  float first[D], width = 0.0f;
  int count[D], cells = 1;
  for (int a = 0; a < D; ++a) {
    if (std::fabs(box[a].lo) >= max_enclosed_noise_coordinate || std::fabs(box[a].hi) >= max_enclosed_noise_coordinate)
      return range;
    first[a] = std::floor(box[a].lo);
    count[a] = static_cast<int>(std::floor(box[a].hi) - first[a]) + 1;
    if (count[a] > max_enclosed_noise_cells) return range;
    cells *= count[a];
    width += box[a].hi - box[a].lo;
  }
  if (cells > max_enclosed_noise_cells || width > max_enclosed_noise_width) return range;
  Interval result{infinity, -infinity};
  for (int cell = 0; cell < cells; ++cell) {
    float corner[D];
    Interval fraction[D];
    for (int a = 0, rest = cell; a < D; rest /= count[a], ++a) {
      corner[a] = first[a] + float(rest % count[a]);
      fraction[a] = {std::max(box[a].lo, corner[a]) - corner[a], std::min(box[a].hi, corner[a] + 1.0f) - corner[a]};
    }
    result = hull(result, over_cell(corner, fraction));
    // The rest of the cells cannot narrow what the proven range bounds.
    if (result.lo - lattice_rounding_margin <= range.lo && result.hi + lattice_rounding_margin >= range.hi) return range;
  }
  return meet(widened(result, lattice_rounding_margin), range);
}

// A knot's offset along an axis of a cell is the box's fraction of the
// cell there minus 0 or 1 (its lattice step), so the knots of a cell share
// 2 D offsets and their weights, bounded once (noise: 6 of 24).
template <int D>
struct KnotOffsets {
  Interval offset[D][2], weight[D][2];

  explicit KnotOffsets(const Interval* fraction) {
    for (int a = 0; a < D; ++a)
      for (int step = 0; step < 2; ++step) {
        offset[a][step] = fraction[a] + (step == 0 ? 0.0f : -1.0f);
        weight[a][step] = noise_weight_over(offset[a][step]);
      }
  }
  // The step of a knot's offset from the corner (0 or -1).
  static int step(float offset) { return offset != 0.0f; }
};

// Noise over the box, cell by cell: within a cell each knot's gradient is
// known, its weights are monotone in the offsets and its slope linear in
// them. `cell_axis(cell, axis)` gives the float axis a cell hashes with.
template <class CellAxis>
Interval noise_over_cells(const NoiseTables& tables, Interval x, Interval y, Interval z, CellAxis cell_axis) {
  const Interval box[3] = {x, y, z};
  return lattice_over_cells(box, lattice_range(x, y, z, noise_bound), [&](const float* corner, const Interval* fraction) {
    const KnotOffsets<3> knots(fraction);
    Interval sum = 0.0f;
    // At the corner itself each knot's offsets are minus its lattice step.
    semantics::for_each_noise_knot(
        tables, corner[0], corner[1], corner[2], cell_axis(corner[0], 0), cell_axis(corner[1], 1),
        cell_axis(corner[2], 2), [&](auto slot, float du, float dv, float dw) {
          const int iu = knots.step(du), iv = knots.step(dv), iw = knots.step(dw);
          const Interval &u = knots.offset[0][iu], &v = knots.offset[1][iv], &w = knots.offset[2][iw];
          const Interval slope = u * tables.hashed_gradient_x[slot] + v * tables.hashed_gradient_y[slot] +
                                 w * tables.hashed_gradient_z[slot];
          sum = sum + knots.weight[0][iu] * knots.weight[1][iv] * knots.weight[2][iw] * slope;
        });
    return sum;
  });
}

// A box's lattice coordinate, by which the overloads below recognise its
// axes: they bound noise cell by cell from each cell's own floats, so the
// hash index of the box as a whole is never read; any slot encloses it.
inline semantics::LatticeCoordinate<Interval> lattice_coordinate(Interval x) {
  return {floor(x), IntervalInt{0, noise_table_size - 1}};
}

inline Interval noise_on_axes(const NoiseTables& tables, Interval x, Interval y, Interval z,
                              const semantics::LatticeAxis<Interval>&, const semantics::LatticeAxis<Interval>&,
                              const semantics::LatticeAxis<Interval>&) {
  return noise_over_cells(tables, x, y, z, [](float cell, int) { return semantics::lattice_axis(cell); });
}

// Periods that differ over the box are bounded by the proven range alone.
inline bool is_one_period(const semantics::PeriodicAxis<Interval>& axis) {
  return is_point(axis.period) && is_finite(axis.period);
}

inline Interval noise_on_axes(const NoiseTables& tables, Interval x, Interval y, Interval z,
                              const semantics::PeriodicAxis<Interval>& ax, const semantics::PeriodicAxis<Interval>& ay,
                              const semantics::PeriodicAxis<Interval>& az) {
  if (!is_one_period(ax) || !is_one_period(ay) || !is_one_period(az)) return lattice_range(x, y, z, noise_bound);
  const float period[3] = {ax.period.lo, ay.period.lo, az.period.lo};
  return noise_over_cells(tables, x, y, z,
                          [&](float cell, int axis) { return semantics::periodic_axis(cell, period[axis]); });
}

// The proven range of noise4. A knot's term is W_k (g . d) with g =
// (G, c), G a unit vector and |c| <= 1 (noise4.h), so |g . d| <= |d_xyz| +
// |d_w|; the 16 weights W_k sum to 1, so by Jensen sum W_k |d_xyz| <=
// sqrt(sum W_k |d_xyz|^2) = sqrt(q(u) + q(v) + q(s)) <= sqrt(3) / 2 and
// sum W_k |d_w| <= sqrt(q(t)) <= 1 / 2, with q as for noise:
// |noise4| <= (sqrt(3) + 1) / 2.
inline constexpr float noise4_bound = 1.3660254f;

// noise4 over the box, cell by cell, as noise_over_cells does in 3D.
template <class CellAxis>
Interval noise4_over_cells(const NoiseTables& tables, Interval x, Interval y, Interval z, Interval w,
                           CellAxis cell_axis) {
  const Interval box[4] = {x, y, z, w};
  const auto gradient = semantics::noise4_gradient_tables(tables);
  auto gradient_at = [&](int slot) {
    return std::array{gradient[0][slot], gradient[1][slot], gradient[2][slot], gradient[3][slot]};
  };
  return lattice_over_cells(box, lattice_range(x, y, z, w, noise4_bound), [&](const float* corner,
                                                                               const Interval* fraction) {
    const KnotOffsets<4> knots(fraction);
    Interval sum = 0.0f;
    semantics::for_each_noise4_knot(
        tables, corner[0], corner[1], corner[2], corner[3], cell_axis(corner[0], 0), cell_axis(corner[1], 1),
        cell_axis(corner[2], 2), cell_axis(corner[3], 3), [&](auto slot, float du, float dv, float ds, float dt) {
          const int iu = knots.step(du), iv = knots.step(dv), is = knots.step(ds), it = knots.step(dt);
          const Interval &u = knots.offset[0][iu], &v = knots.offset[1][iv], &s = knots.offset[2][is],
                         &t = knots.offset[3][it];
          sum = sum + knots.weight[0][iu] * knots.weight[1][iv] * knots.weight[2][is] * knots.weight[3][it] *
                          semantics::noise4_slope(gradient_at(slot), u, v, s, t);
        });
    return sum;
  });
}

inline Interval noise4_on_axes(const NoiseTables& tables, Interval x, Interval y, Interval z, Interval w,
                               const semantics::LatticeAxis<Interval>&, const semantics::LatticeAxis<Interval>&,
                               const semantics::LatticeAxis<Interval>&, const semantics::LatticeAxis<Interval>&) {
  return noise4_over_cells(tables, x, y, z, w, [](float cell, int) { return semantics::lattice_axis(cell); });
}

inline Interval noise4_on_axes(const NoiseTables& tables, Interval x, Interval y, Interval z, Interval w,
                               const semantics::PeriodicAxis<Interval>& ax, const semantics::PeriodicAxis<Interval>& ay,
                               const semantics::PeriodicAxis<Interval>& az,
                               const semantics::PeriodicAxis<Interval>& aw) {
  if (!is_one_period(ax) || !is_one_period(ay) || !is_one_period(az) || !is_one_period(aw))
    return lattice_range(x, y, z, w, noise4_bound);
  const float period[4] = {ax.period.lo, ay.period.lo, az.period.lo, aw.period.lo};
  return noise4_over_cells(tables, x, y, z, w,
                           [&](float cell, int axis) { return semantics::periodic_axis(cell, period[axis]); });
}

// F1 and F2 over a box: the nearest feature point lies in p's own cell
// (F1 <= sqrt(3)), the second nearest no further than the point of a
// face neighbour (F2 <= sqrt(2^2 + 1 + 1)).
inline constexpr float cellular_nearest_bound = 1.7320508f;
inline constexpr float cellular_second_bound = 2.4494897f;

template <class Axis>
semantics::CellularDistances<Interval> cellular_on_axes(const NoiseTables&, Interval x, Interval y, Interval z,
                                                        Interval, const Axis&, const Axis&, const Axis&) {
  if (is_everything(lattice_range(x, y, z, 0.0f))) return {everything(), everything()};
  return {{0.0f, cellular_nearest_bound + lattice_rounding_margin},
          {0.0f, cellular_second_bound + lattice_rounding_margin}};
}

// The gradient of noise, per component: the weights' derivatives are at
// most 3/2 and sum, over the knots, to at most 3 along each axis, times
// |g . d| <= sqrt(3), plus sum W_k |g| <= 1 (dnoise's own interval form).
inline constexpr float noise_derivative_bound = 6.1961524f;

// Improved noise: Perlin 2002's gradients are edge vectors of length
// sqrt(2), its lerp weights (1 - f, f) sum to 1 and
// (1 - f(t)) t^2 + f(t) (1 - t)^2 <= 1/4 too (tested), so as for noise,
// |noise_improved| <= sqrt(2) sqrt(3/4) (its own interval form).
inline constexpr float improved_noise_bound = 1.2247449f;

}  // namespace shadetree::lanes
