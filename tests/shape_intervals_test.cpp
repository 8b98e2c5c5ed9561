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

// A component of d / |d| in float: 1 up to rounding, but where |d|^2 is
// subnormal, rounded to a multiple of 2^-149, up to sqrt(1.5) (a squared
// length of 1.49 2^-149 read as 2^-149). The bound covers both.
TEST(ShapeIntervals, UnitVectorsOfSubnormalLengthReachPastOne) {
  float largest = 0.0f;
  for (int k = 1; k < 4000; ++k) {
    const float x = std::sqrt(static_cast<float>(k) / 1000.0f) * std::ldexp(1.0f, -75);
    const float v[3] = {x, 0.0f, 0.0f};
    float unit[3];
    semantics::normalize_n(v, 3, unit);
    largest = std::max(largest, unit[0]);
    const Interval squared{x * x, x * x};
    EXPECT_LE(unit[0], lanes::unit_component_bound(squared)) << x;
  }
  EXPECT_GT(largest, 1.1f) << "subnormal squares round by a large share";
  EXPECT_LE(largest, 1.25f);
  EXPECT_EQ(lanes::unit_component_bound({FLT_MIN, 1.0f}), 1.0f + 1e-6f);
}

}  // namespace
}  // namespace shadetree
