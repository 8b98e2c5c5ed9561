// The interval forms that know an op's shape (nodes/semantics/shape_intervals.h):
// each encloses what the float lane computes at every point of random
// boxes, and is tight where the generic form was not.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "nodes/interval_frame.h"
#include "nodes/semantics/shape_intervals.h"
#include "nodes/semantics/vector.h"

namespace shadetree {
namespace {

using lanes::Interval;
using semantics::SplineBasis;

std::mt19937 random_source(int seed) { return std::mt19937(static_cast<unsigned>(seed)); }

float uniform(std::mt19937& random, float lo, float hi) {
  return std::uniform_real_distribution<float>(lo, hi)(random);
}

// A box of x over [-0.3, 1.3] (the clamp to [0, 1] included), from a point up to all of it.
Interval random_box(std::mt19937& random) {
  const float a = uniform(random, -0.3f, 1.3f), width = uniform(random, 0.0f, 1.0f) * uniform(random, 0.0f, 1.0f);
  return {a, a + width};
}

// Points of the box: its ends and points between.
std::vector<float> points_of(Interval box, std::mt19937& random) {
  std::vector<float> points = {box.lo, box.hi};
  for (int k = 0; k < 30; ++k) points.push_back(std::min(box.hi, box.lo + (box.hi - box.lo) * uniform(random, 0, 1)));
  return points;
}

TEST(ShapeIntervals, SplinesEncloseEveryBasisOverRandomBoxes) {
  std::mt19937 random = random_source(5);
  for (SplineBasis basis : {SplineBasis::catmull_rom, SplineBasis::linear, SplineBasis::step}) {
    for (int trial = 0; trial < 400; ++trial) {
      const int count = 4 + static_cast<int>(uniform(random, 0, 9)), components = trial % 3 + 1;
      std::vector<float> knots(static_cast<std::size_t>(count * components));
      for (float& knot : knots) knot = uniform(random, -5.0f, 5.0f);
      const Interval box = random_box(random);
      for (int c = 0; c < components; ++c) {
        const Interval range = lanes::spline_range(knots.data(), count, components, c, basis, box);
        for (float x : points_of(box, random)) {
          const float value = semantics::spline(knots.data(), count, components, c, basis, x);
          ASSERT_TRUE(lanes::encloses(range, value))
              << "basis " << static_cast<int>(basis) << ", x " << x << " in [" << box.lo << ", " << box.hi
              << "]: " << value << " outside [" << range.lo << ", " << range.hi << "]";
        }
      }
    }
  }
}

// Gilet & Dischler's shape transfer function of stf_holes, over the
// indices (1 + noise) / 2 takes in any brick: its values' range, [0, 1],
// where the generic form gave [-9.3, 10.3].
TEST(ShapeIntervals, AShapeTransferFunctionStaysWithinItsValues) {
  const float values[] = {0, 0, 0, 0.5f, 1, 1, 1, 0.5f, 0, 0, 0};
  const Interval range = lanes::spline_range(values, 11, 1, 0, SplineBasis::linear, {0.0669373f, 0.933063f});
  EXPECT_NEAR(range.lo, 0.0f, 1e-4f);
  EXPECT_NEAR(range.hi, 1.0f, 1e-4f);
  // Over one segment, its two knots.
  const Interval segment = lanes::spline_range(values, 11, 1, 0, SplineBasis::linear, {0.31f, 0.39f});
  EXPECT_NEAR(segment.lo, 0.5f, 1e-4f);
  EXPECT_NEAR(segment.hi, 1.0f, 1e-4f);
  // Where NaN may come in, the lanes read 0: the first knot.
  const Interval anything = lanes::spline_range(values, 11, 1, 0, SplineBasis::linear, lanes::everything());
  EXPECT_NEAR(anything.lo, 0.0f, 1e-4f);
  EXPECT_NEAR(anything.hi, 1.0f, 1e-4f);
}

TEST(ShapeIntervals, Table2dEnclosesItsBilinearLookup) {
  std::mt19937 random = random_source(9);
  for (int trial = 0; trial < 400; ++trial) {
    const int rows = 1 + static_cast<int>(uniform(random, 0, 6)), columns = 1 + static_cast<int>(uniform(random, 0, 6));
    std::vector<float> values(static_cast<std::size_t>(rows * columns));
    for (float& value : values) value = uniform(random, -2.0f, 2.0f);
    const Interval x = random_box(random), y = random_box(random);
    const Interval range = lanes::table2d_range(values.data(), rows, columns, x, y);
    for (float u : points_of(x, random))
      for (float v : points_of(y, random)) {
        const float value = semantics::table2d(values.data(), rows, columns, u, v);
        ASSERT_TRUE(lanes::encloses(range, value)) << rows << "x" << columns << " at " << u << ", " << v;
      }
  }
}

// A distance grid of 5 x 4 x 3 voxels of 0.5 from (-1, -1, -1) (the layout
// of nodes/semantics/soft_objects.h), its distances random, and boxes of
// p from a point to wider than the grid, inside, across and beyond it.
TEST(ShapeIntervals, GridDistanceEnclosesItsTrilinearLookupAndTheDistanceBeyond) {
  std::mt19937 random = random_source(11);
  const int size[3] = {5, 4, 3};
  std::vector<float> grid = {-1.0f, -1.0f, -1.0f, 0.5f, float(size[0]), float(size[1]), float(size[2])};
  for (int v = 0; v < size[0] * size[1] * size[2]; ++v) grid.push_back(uniform(random, -1.0f, 2.0f));
  for (int trial = 0; trial < 2000; ++trial) {
    Interval box[3];
    for (Interval& axis : box) {
      const float a = uniform(random, -3.0f, 3.0f), width = uniform(random, 0.0f, 3.0f) * uniform(random, 0.0f, 1.0f);
      axis = {a, a + width};
    }
    const Interval range = lanes::grid_distance_range(grid.data(), box[0], box[1], box[2]);
    for (int k = 0; k < 40; ++k) {
      semantics::Vec3<float> p;
      float* at[3] = {&p.x, &p.y, &p.z};
      for (int axis = 0; axis < 3; ++axis)
        *at[axis] = k < 2 ? (k == 0 ? box[axis].lo : box[axis].hi)
                          : std::min(box[axis].hi, box[axis].lo + (box[axis].hi - box[axis].lo) * uniform(random, 0, 1));
      const float value = semantics::grid_distance(grid.data(), p);
      ASSERT_TRUE(lanes::encloses(range, value)) << "at " << p.x << ", " << p.y << ", " << p.z << ": " << value
                                                 << " outside [" << range.lo << ", " << range.hi << "]";
    }
  }
  // Within one voxel cell, between its eight values; beyond the last
  // voxel centre (1.25, 0.75, 0.25) by (3, 4, 12), 13 further than the
  // last cell's values.
  const auto cell_hull = [&](int i0, int j0, int k0) {
    float least = grid[7 + (k0 * size[1] + j0) * size[0] + i0], most = least;
    for (int k = k0; k < k0 + 2; ++k)
      for (int j = j0; j < j0 + 2; ++j)
        for (int i = i0; i < i0 + 2; ++i) {
          least = std::min(least, grid[7 + (k * size[1] + j) * size[0] + i]);
          most = std::max(most, grid[7 + (k * size[1] + j) * size[0] + i]);
        }
    return Interval{least, most};
  };
  const Interval cell = lanes::grid_distance_range(grid.data(), {-0.7f, -0.6f}, {-0.7f, -0.6f}, {-0.7f, -0.6f});
  EXPECT_NEAR(cell.lo, cell_hull(0, 0, 0).lo, 1e-3f);
  EXPECT_NEAR(cell.hi, cell_hull(0, 0, 0).hi, 1e-3f);
  const Interval far = lanes::grid_distance_range(grid.data(), 4.25f, 4.75f, 12.25f);
  EXPECT_NEAR(far.lo, cell_hull(3, 2, 1).lo + 13.0f, 1e-3f);
  EXPECT_NEAR(far.hi, cell_hull(3, 2, 1).hi + 13.0f, 1e-3f);
}

// d / |d| in float is a unit vector to rounding however short d is: where
// its squares underflow (rounded to a multiple of 2^-149, a subnormal sum
// could be a third short and made components of up to sqrt(1.5); rounded
// to 0, a vector that is not zero normalized to 0) it is scaled first.
TEST(ShapeIntervals, TinyVectorsNormalizeToUnitVectors) {
  for (int k = 1; k < 4000; ++k) {
    for (float scale : {std::ldexp(1.0f, -75), std::ldexp(1.0f, -100), std::ldexp(1.0f, -140), 1.0f}) {
      const float x = std::sqrt(static_cast<float>(k) / 1000.0f) * scale;
      const float v[3] = {x, -0.5f * x, 0.25f * x};
      float unit[3];
      semantics::normalize_n(v, 3, unit);
      const double length = std::sqrt(double(unit[0]) * unit[0] + double(unit[1]) * unit[1] + double(unit[2]) * unit[2]);
      ASSERT_LE(length, lanes::unit_length_bound) << x;
      ASSERT_GE(length, 1.0 - 1e-6) << x;
      ASSERT_GT(unit[0], 0.0f) << x;
    }
  }
  const float zero[3] = {0.0f, 0.0f, 0.0f};
  float unit[3];
  semantics::normalize_n(zero, 3, unit);
  EXPECT_EQ(unit[0], 0.0f);
  EXPECT_EQ(unit[1], 0.0f);
  EXPECT_EQ(unit[2], 0.0f);
}

}  // namespace
}  // namespace shadetree
