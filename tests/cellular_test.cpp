// Worley 1996 cellular noise: closed forms with the feature points at the
// cell centres, and the properties of distance functions everywhere.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "nodes/semantics/cellular.h"

namespace shadetree {
namespace {

const NoiseTables& tables() { return noise_tables(default_noise_seed); }

// With jitter 0 the feature points are the cell centres: F1 is the distance
// to the own cell's centre, and the second-nearest centre is the neighbour
// across the face nearest p, so F2^2 = F1^2 + 1 - 2 max|offset|.
TEST(Cellular, WithoutJitterTheFeaturePointsAreCellCentres) {
  const float offsets[][3] = {{0.1f, 0.2f, 0.3f}, {-0.4f, 0.05f, 0.0f}, {0.25f, -0.25f, 0.45f}};
  for (const auto& offset : offsets) {
    const float x = 3.5f + offset[0], y = -7.5f + offset[1], z = 0.5f + offset[2];
    const auto distances = semantics::cellular(tables(), x, y, z, 0.0f);
    const float f1_squared = offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2];
    const float largest = std::max({std::fabs(offset[0]), std::fabs(offset[1]), std::fabs(offset[2])});
    EXPECT_NEAR(distances.nearest, std::sqrt(f1_squared), 1e-6f);
    EXPECT_NEAR(distances.second, std::sqrt(f1_squared + 1.0f - 2.0f * largest), 1e-6f);
  }
}

// Distances to a point set: 0 <= F1 <= F2, and F1 moves no faster than p
// (|F1(p) - F1(q)| <= |p - q|).
TEST(Cellular, IsADistanceFunction) {
  std::mt19937 random(1996);
  std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f), step(-0.3f, 0.3f);
  for (int i = 0; i < 2000; ++i) {
    const float p[3] = {coordinate(random), coordinate(random), coordinate(random)};
    const float d[3] = {step(random), step(random), step(random)};
    const auto at_p = semantics::cellular(tables(), p[0], p[1], p[2], 1.0f);
    const auto at_q = semantics::cellular(tables(), p[0] + d[0], p[1] + d[1], p[2] + d[2], 1.0f);
    ASSERT_GE(at_p.nearest, 0.0f);
    ASSERT_LE(at_p.nearest, at_p.second);
    ASSERT_LE(at_p.nearest, std::sqrt(3.0f));  // the own cell's point is within the cell
    const float moved = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    ASSERT_LE(std::fabs(at_p.nearest - at_q.nearest), moved + 1e-4f) << i;
  }
}

TEST(Cellular, SeedsMoveTheFeaturePoints) {
  const auto one = semantics::cellular(noise_tables(1), 0.3f, 0.6f, 0.9f, 1.0f);
  const auto other = semantics::cellular(noise_tables(2), 0.3f, 0.6f, 0.9f, 1.0f);
  EXPECT_NE(one.nearest, other.nearest);
}

}  // namespace
}  // namespace shadetree
