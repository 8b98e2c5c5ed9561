// Soft objects and generalized booleans (Perlin & Hoffert 1989 sections 2.1, 2.2).
#include <gtest/gtest.h>

#include "nodes/semantics/soft_objects.h"

namespace shadetree::semantics {
namespace {

const Vec3<float> origin{0.0f, 0.0f, 0.0f};

TEST(SoftSphere, DensityIsOneInsideInnerRadius) {
  EXPECT_EQ(soft_sphere(Vec3<float>{0.2f, 0.1f, 0.0f}, origin, 1.0f, 0.4f), 1.0f);
  EXPECT_EQ(soft_sphere(Vec3<float>{0.8f, 0.0f, 0.0f}, origin, 1.0f, 0.4f), 1.0f);
}

TEST(SoftSphere, DensityIsZeroOutsideOuterRadius) {
  EXPECT_EQ(soft_sphere(Vec3<float>{1.2f, 0.0f, 0.0f}, origin, 1.0f, 0.4f), 0.0f);
  EXPECT_EQ(soft_sphere(Vec3<float>{0.0f, 3.0f, 0.0f}, origin, 1.0f, 0.4f), 0.0f);
}

// Between the radii: (r0^2 - rx^2) / (r0^2 - r1^2).
TEST(SoftSphere, SoftRegionFollowsThePaperFormula) {
  const float r0 = 1.2f, r1 = 0.8f, rx = 1.0f;
  EXPECT_FLOAT_EQ(soft_sphere(Vec3<float>{0.0f, 0.0f, rx}, origin, 1.0f, 0.4f),
                  (r0 * r0 - rx * rx) / (r0 * r0 - r1 * r1));
  EXPECT_FLOAT_EQ(soft_sphere(Vec3<float>{2.0f, 0.0f, 1.0f}, Vec3<float>{2.0f, 0.0f, 0.0f}, 1.0f, 0.4f),
                  (r0 * r0 - rx * rx) / (r0 * r0 - r1 * r1));
}

TEST(SoftBox, IsOneInsideHalfAtTheSurfaceZeroOutside) {
  const Vec3<float> half{1.0f, 0.5f, 0.5f};
  EXPECT_EQ(soft_box(origin, origin, half, 0.2f), 1.0f);
  EXPECT_FLOAT_EQ(soft_box(Vec3<float>{1.0f, 0.0f, 0.0f}, origin, half, 0.2f), 0.5f);
  EXPECT_EQ(soft_box(Vec3<float>{1.2f, 0.0f, 0.0f}, origin, half, 0.2f), 0.0f);
}

TEST(SoftTorus, IsOneOnTheCoreCircleAndHalfAtTheSurface) {
  EXPECT_EQ(soft_torus(Vec3<float>{1.0f, 0.0f, 0.0f}, origin, 1.0f, 0.25f, 0.1f), 1.0f);
  EXPECT_FLOAT_EQ(soft_torus(Vec3<float>{0.0f, 1.25f, 0.0f}, origin, 1.0f, 0.25f, 0.1f), 0.5f);
  EXPECT_EQ(soft_torus(origin, origin, 1.0f, 0.25f, 0.1f), 0.0f);
}

TEST(GeneralizedBooleans, MatchTheirFormulas) {
  for (float a : {0.0f, 0.25f, 0.6f, 1.0f})
    for (float b : {0.0f, 0.5f, 0.9f, 1.0f}) {
      EXPECT_FLOAT_EQ(soft_intersect(a, b), a * b);
      EXPECT_FLOAT_EQ(soft_union(a, b), a + b - a * b);
      EXPECT_FLOAT_EQ(soft_difference(a, b), a - a * b);
      EXPECT_FLOAT_EQ(soft_complement(a), 1.0f - a);
      // A - B = A and not B; A or B = not (not A and not B).
      EXPECT_FLOAT_EQ(soft_difference(a, b), soft_intersect(a, soft_complement(b)));
      EXPECT_NEAR(soft_union(a, b), soft_complement(soft_intersect(soft_complement(a), soft_complement(b))), 1e-6f);
    }
}

}  // namespace
}  // namespace shadetree::semantics
