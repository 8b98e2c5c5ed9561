// Soft objects and generalized booleans (Perlin & Hoffert 1989 sections 2.1, 2.2),
// and the closest points of their surfaces (section 2.4's project).
#include <gtest/gtest.h>

#include <cmath>

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


float distance(const Vec3<float>& a, const Vec3<float>& b) {
  const Vec3<float> d{a.x - b.x, a.y - b.y, a.z - b.z};
  return std::sqrt(dot3(d, d));
}

TEST(ClosestOnSphere, ProjectsAlongTheRadius) {
  const Vec3<float> q = closest_on_sphere<float>({3.0f, 4.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 2.0f);
  const float scale = 2.0f / std::sqrt(9.0f + 16.0f + 1.0f);
  EXPECT_FLOAT_EQ(q.x, 3.0f * scale);
  EXPECT_FLOAT_EQ(q.y, 4.0f * scale);
  EXPECT_FLOAT_EQ(q.z, 1.0f - scale);
  const Vec3<float> top = closest_on_sphere<float>({0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}, 2.0f);
  EXPECT_EQ(top.y, 2.0f);
}

// The closest point lies on the surface, at the distance the torus's own
// distance function gives, for points inside and outside the tube.
TEST(ClosestOnTorus, LiesOnTheSurfaceAtTheSurfaceDistance) {
  const float major = 1.5f, minor = 0.4f;
  for (const Vec3<float> p : {Vec3<float>{2.5f, 0.0f, 0.3f}, Vec3<float>{-0.4f, 1.2f, -0.1f},
                              Vec3<float>{0.7f, -0.9f, 0.9f}, Vec3<float>{1.5f, 0.0f, 0.1f}}) {
    const Vec3<float> q = closest_on_torus<float>(p, {0.0f, 0.0f, 0.0f}, major, minor);
    const float ring = std::sqrt(q.x * q.x + q.y * q.y) - major;
    EXPECT_NEAR(std::sqrt(ring * ring + q.z * q.z), minor, 1e-5f);
    const float p_ring = std::sqrt(p.x * p.x + p.y * p.y) - major;
    EXPECT_NEAR(distance(p, q), std::fabs(std::sqrt(p_ring * p_ring + p.z * p.z) - minor), 1e-5f);
  }
  // On the axis and on the core circle: the fallbacks stay on the surface.
  const Vec3<float> axis = closest_on_torus<float>({0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 0.0f}, major, minor);
  EXPECT_NEAR(distance(axis, {major, 0.0f, 0.0f}), minor, 1e-5f);
  const Vec3<float> core = closest_on_torus<float>({0.0f, major, 0.0f}, {0.0f, 0.0f, 0.0f}, major, minor);
  EXPECT_NEAR(core.y, major + minor, 1e-5f);
}

}  // namespace
}  // namespace shadetree::semantics
