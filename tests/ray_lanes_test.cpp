#include "render/ray_lanes.h"

#include <gtest/gtest.h>

namespace shadetree {
namespace {

// A ray along +x from the origin through [1, 2.25] at step 0.5: segments
// [1, 1.5], [1.5, 2], [2, 2.25].
RayLanes one_ray(float jitter, int first_segment = 0) {
  RayLanes lanes(0.5f);
  lanes.add({0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 1.0f, 2.25f, jitter, first_segment, 7);
  return lanes;
}

TEST(RayLanes, SamplesLieJitterOfTheWayAlongTheirSegments) {
  RayLanes lanes = one_ray(0.25f);
  EXPECT_FLOAT_EQ(lanes.sample_t(0, 0), 1.125f);
  EXPECT_FLOAT_EQ(lanes.sample_t(0, 1), 1.625f);
  // The last segment is clipped at the exit: a quarter of its 0.25.
  EXPECT_FLOAT_EQ(lanes.segment_length(0, 2), 0.25f);
  EXPECT_FLOAT_EQ(lanes.sample_t(0, 2), 2.0625f);
  // The probe before the entry lies a step before the first sample.
  EXPECT_FLOAT_EQ(lanes.sample_t(0, -1), 0.625f);
}

TEST(RayLanes, ARayHasSegmentsLeftUntilItsLastIsMarched) {
  RayLanes lanes = one_ray(0.5f);
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(lanes.has_segments_left(0)) << k;
    ++lanes.segment[0];
  }
  EXPECT_FALSE(lanes.has_segments_left(0));
}

TEST(RayLanes, AdvancingPassesWhatSteppingOneSegmentAtATimeWould) {
  // A long ray, and targets before, among and past its samples.
  for (const float target : {0.5f, 1.3f, 7.77f, 40.0f, 1000.0f}) {
    RayLanes jumped(0.01f), stepped(0.01f);
    jumped.add({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f, 41.003f, 0.3f, 0, 0);
    stepped.add({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f, 41.003f, 0.3f, 0, 0);
    int passed = 0;
    while (stepped.segment_start(0, stepped.segment[0] + 1) < stepped.exit[0] &&
           stepped.sample_t(0, stepped.segment[0] + 1) < target) {
      ++stepped.segment[0];
      ++passed;
    }
    EXPECT_EQ(jumped.advance_to_last_sample_before(0, target), passed) << target;
    EXPECT_EQ(jumped.segment[0], stepped.segment[0]) << target;
  }
}

TEST(RayLanes, CompositingIsFrontToBack) {
  RayLanes lanes = one_ray(0.5f);
  lanes.composite(0, 0.5f, {1.0f, 0.0f, 0.0f});
  lanes.composite(0, 0.5f, {0.0f, 1.0f, 0.0f});
  // The second sample is seen through what the first lets through.
  EXPECT_FLOAT_EQ(lanes.alpha[0], 0.75f);
  EXPECT_FLOAT_EQ(lanes.color_of(0).x, 0.5f);
  EXPECT_FLOAT_EQ(lanes.color_of(0).y, 0.25f);
}

TEST(RayLanes, AMovedRayKeepsItsState) {
  RayLanes lanes(0.5f);
  lanes.add({1.0f, 2.0f, 3.0f}, {0.0f, 0.0f, 1.0f}, 0.5f, 4.0f, 0.1f, -1, 3);
  lanes.add({4.0f, 5.0f, 6.0f}, {1.0f, 0.0f, 0.0f}, 0.25f, 2.0f, 0.9f, 0, 9);
  lanes.composite(1, 0.5f, {0.2f, 0.4f, 0.6f});
  lanes.move(1, 0);
  lanes.truncate(1);
  ASSERT_EQ(lanes.size(), 1u);
  EXPECT_EQ(lanes.record[0], 9u);
  EXPECT_EQ(lanes.origin_of(0), glm::vec3(4.0f, 5.0f, 6.0f));
  EXPECT_EQ(lanes.along_of(0), glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_FLOAT_EQ(lanes.sample_t(0), 0.25f + 0.9f * 0.5f);
  EXPECT_FLOAT_EQ(lanes.alpha[0], 0.5f);
  EXPECT_FLOAT_EQ(lanes.color_of(0).z, 0.3f);
}

TEST(RayLanes, ARaySetOutAfreshStartsWithItsProbe) {
  RayLanes lanes = one_ray(0.5f);
  lanes.segment[0] = 2;
  lanes.occupied_until[0] = 1.8f;
  lanes.set_out(0, {1.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 3.0f);
  EXPECT_EQ(lanes.segment[0], -1);
  EXPECT_FLOAT_EQ(lanes.entry[0], 0.0f);
  EXPECT_FLOAT_EQ(lanes.exit[0], 3.0f);
  EXPECT_LT(lanes.occupied_until[0], 0.0f);
  EXPECT_EQ(lanes.point(0, 2.0f), glm::vec3(1.5f, 2.0f, 0.0f));
}

}  // namespace
}  // namespace shadetree
