// Interval forms that know the shape of what an op computes, where the
// generic form (the semantics over intervals) loses it to the dependency
// problem: a spline's fraction t - floor(t) over a box of t spans far more
// than [0, 1], and a unit vector d / |d| over a box holding short vectors
// spans everything. Without them a Gilet & Dischler shape transfer
// function over a brick of the volume came out as [-9.3, 10.3] for values
// in [0, 1], and no brick of the STF volumes was ever found empty.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "nodes/lane_interval.h"
#include "nodes/semantics/soft_objects.h"
#include "nodes/semantics/splines.h"

namespace shadetree::lanes {

// Blending a few values by weights that sum to 1 (a spline's basis, a
// bilinear lookup) rounds by a few ulps of the largest of them.
inline constexpr float blend_rounding = 4e-5f;

inline Interval widened_by_rounding(Interval x) {
  return widened(x, blend_rounding * std::max(std::fabs(x.lo), std::fabs(x.hi)));
}

// The hull of values[first .. last] (every `stride`-th float from `values`).
inline Interval hull_of(const float* values, int stride, int first, int last) {
  Interval result{values[first * stride], values[first * stride]};
  for (int k = first + 1; k <= last; ++k) result = hull(result, Interval(values[k * stride]));
  return result;
}

// semantics::spline over x: the hull of each segment it may reach. A
// linear segment lies between its two knots; a Catmull-Rom segment
// between its Bezier control points k1, k1 + (k2 - k0) / 6,
// k2 - (k3 - k1) / 6 and k2 (the convex hull property).
inline Interval spline_range(const float* knots, int count, int components, int component,
                             semantics::SplineBasis basis, Interval x) {
  using semantics::SplineBasis;
  const Interval clamped = semantics::unit_clamp(x);  // NaN reads as 0, as on the lanes
  const float* values = knots + component;
  if (basis == SplineBasis::step) {
    const auto index = [&](float at) { return std::min(static_cast<int>(std::floor(at * float(count))), count - 1); };
    return hull_of(values, components, index(clamped.lo), index(clamped.hi));
  }
  const int segments = basis == SplineBasis::catmull_rom ? count - 3 : count - 1;
  if (segments <= 0) return values[0];
  const auto segment = [&](float at) {
    return static_cast<int>(std::min(std::floor(at * float(segments)), float(segments - 1)));
  };
  const int first = segment(clamped.lo), last = segment(clamped.hi);
  if (basis == SplineBasis::linear) return widened_by_rounding(hull_of(values, components, first, last + 1));
  const auto knot = [&](int k) { return values[k * components]; };
  Interval result = knot(first + 1);
  for (int s = first; s <= last; ++s) {
    const float k0 = knot(s), k1 = knot(s + 1), k2 = knot(s + 2), k3 = knot(s + 3);
    for (float control : {k1, k1 + (k2 - k0) / 6.0f, k2 - (k3 - k1) / 6.0f, k2}) result = hull(result, Interval(control));
  }
  return widened_by_rounding(result);
}

// semantics::table2d over (x, y): the hull of the grid values of every
// cell it may reach (a bilinear patch lies between its corners).
inline Interval table2d_range(const float* values, int rows, int columns, Interval x, Interval y) {
  const auto cells = [](Interval coordinate, int size, int& first, int& last) {
    const Interval clamped = semantics::unit_clamp(coordinate);
    const auto cell = [&](float at) {
      return static_cast<int>(std::min(std::floor(at * float(size - 1)), float(size > 1 ? size - 2 : 0)));
    };
    first = cell(clamped.lo);
    last = std::min(cell(clamped.hi) + 1, size - 1);
  };
  int column_first, column_last, row_first, row_last;
  cells(x, columns, column_first, column_last);
  cells(y, rows, row_first, row_last);
  Interval result = values[row_first * columns + column_first];
  for (int row = row_first; row <= row_last; ++row)
    result = hull(result, hull_of(values + row * columns, 1, column_first, column_last));
  return widened_by_rounding(result);
}

// Boxes over more voxels than this are bounded by nothing (the occupancy
// grid's bricks reach some hundreds of a 64^3 grid).
inline constexpr long max_enclosed_voxels = 1 << 15;

// semantics::grid_distance over a box of p: a trilinear blend lies
// between the voxel values it blends, so between those of every cell the
// box reaches, and the distance beyond the grid it adds grows with how
// far the box reaches past it. The generic form knew neither: its gather
// spans whole slices of the grid, and mesh_hypertexture found none of its
// bounds empty.
inline Interval grid_distance_range(const float* grid, Interval x, Interval y, Interval z) {
  if (!is_finite(x) || !is_finite(y) || !is_finite(z)) return everything();
  const float voxel = grid[3];
  const int size[3] = {int(grid[4]), int(grid[5]), int(grid[6])};
  const Interval p[3] = {x, y, z};
  int first[3], last[3];
  long voxels = 1;
  Interval outside = 0.0f;
  for (int axis = 0; axis < 3; ++axis) {
    // As the lane form computes them, endpoint by endpoint: each step is
    // monotone in p.
    const float lo = grid[axis] + 0.5f * voxel, hi = grid[axis] + (float(size[axis]) - 0.5f) * voxel;
    const auto clamped = [&](float at) { return std::min(std::max(at, lo), hi); };
    const Interval beyond{p[axis].lo - clamped(p[axis].lo), p[axis].hi - clamped(p[axis].hi)};
    outside = outside + square(beyond);
    const auto cell = [&](float at) {
      const float position = (clamped(at) - lo) * (1.0f / voxel);
      return static_cast<int>(std::min(std::floor(position), float(size[axis] > 1 ? size[axis] - 2 : 0)));
    };
    first[axis] = cell(p[axis].lo);
    last[axis] = size[axis] > 1 ? cell(p[axis].hi) + 1 : first[axis];
    voxels *= last[axis] - first[axis] + 1;
  }
  if (voxels > max_enclosed_voxels) return everything();
  const float* distance = grid + semantics::distance_grid_header;
  Interval blended{distance[(static_cast<std::size_t>(first[2]) * size[1] + first[1]) * size[0] + first[0]]};
  for (int k = first[2]; k <= last[2]; ++k)
    for (int j = first[1]; j <= last[1]; ++j)
      blended = hull(blended, hull_of(distance + (static_cast<std::size_t>(k) * size[1] + j) * size[0], 1, first[0],
                                      last[0]));
  return widened_by_rounding(blended) + sqrt(outside);
}

// How long d / |d| computed in float can be (semantics::normalize_n), and
// so how far from 0 its components lie: 1 up to rounding.
inline constexpr float unit_length_bound = 1.0f + 1e-6f;

// x narrowed to centre + [-reach, reach] (centre a finite interval, reach
// >= 0), with the rounding of computing centre + a value within reach.
inline Interval within_reach(Interval x, Interval centre, float reach) {
  const Interval around{centre.lo - reach, centre.hi + reach};
  return meet(x, widened_by_rounding(around));
}

}  // namespace shadetree::lanes
