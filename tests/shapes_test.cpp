// Ray hits of the analytic objects against their closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "scene/shapes.h"

namespace shadetree {
namespace {

constexpr float inf = INFINITY;

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Sphere, HitFromOutsideMeetsTheNearSideWithTheOutwardNormal) {
  const auto hit = intersect(Sphere{2.0f}, Ray{{0, 0, 5}, {0, 0, -1}}, 0.0f, inf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 3.0f, 1e-6f);
  expect_near(hit->normal, {0, 0, 1});
  EXPECT_NEAR(hit->uv.x, 0.75f, 1e-6f) << "+z is three quarters of a turn from +x, counter-clockwise from above";
  EXPECT_NEAR(hit->uv.y, 0.5f, 1e-6f);
}

TEST(Sphere, ParameterIsAlongTheUnnormalizedDirection) {
  const auto hit = intersect(Sphere{1.0f}, Ray{{0, 0, 5}, {0, 0, -4}}, 0.0f, inf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1.0f, 1e-6f);
}

TEST(Sphere, RayFromInsideHitsTheFarSideAndRangesAreRespected) {
  const auto inside = intersect(Sphere{1.0f}, Ray{{0, 0, 0}, {1, 0, 0}}, 0.0f, inf);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(inside->t, 1.0f, 1e-6f);
  expect_near(inside->normal, {1, 0, 0});
  EXPECT_FALSE(intersect(Sphere{1.0f}, Ray{{0, 0, 5}, {0, 0, -1}}, 0.0f, 3.9f));
  EXPECT_FALSE(intersect(Sphere{1.0f}, Ray{{0, 2, 5}, {0, 0, -1}}, 0.0f, inf));
}

TEST(Torus, HitFromAboveMeetsTheTopOfTheTube) {
  const Torus torus{1.0f, 0.25f};
  const auto hit = intersect(torus, Ray{{1, 5, 0}, {0, -1, 0}}, 0.0f, inf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 4.75f, 1e-4f);
  expect_near(hit->normal, {0, 1, 0}, 1e-3f);
  EXPECT_NEAR(hit->uv.y, 0.25f, 1e-3f) << "a quarter of the way round the tube, from the outer equator up";
}

TEST(Torus, RaysThroughTheHoleMissAndSideRaysMeetTheOuterEquator) {
  const Torus torus{1.0f, 0.25f};
  EXPECT_FALSE(intersect(torus, Ray{{0, 5, 0}, {0, -1, 0}}, 0.0f, inf));
  const auto side = intersect(torus, Ray{{5, 0, 0}, {-2, 0, 0}}, 0.0f, inf);
  ASSERT_TRUE(side);
  EXPECT_NEAR(side->t, (5.0f - 1.25f) / 2.0f, 1e-4f);
  expect_near(side->normal, {1, 0, 0}, 1e-3f);
  EXPECT_NEAR(side->uv.y, 0.0f, 1e-3f);
  // Started inside the near tube, the ray leaves it through its inner
  // wall; started past that, it crosses the hole to the far tube.
  const auto inside = intersect(torus, Ray{{5, 0, 0}, {-1, 0, 0}}, 4.0f, inf);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(inside->t, 4.25f, 1e-4f);
  const auto far = intersect(torus, Ray{{5, 0, 0}, {-1, 0, 0}}, 4.3f, inf);
  ASSERT_TRUE(far);
  EXPECT_NEAR(far->t, 5.75f, 1e-4f);
}

TEST(Torus, RandomHitsLieOnTheSurfaceWithTheGradientAsNormal) {
  const Torus torus{1.0f, 0.4f};
  std::mt19937 random(1985);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 origin = glm::normalize(glm::vec3(unit(random), unit(random), unit(random))) * 4.0f;
    const glm::vec3 target(unit(random) * 1.4f, unit(random) * 0.4f, unit(random) * 1.4f);
    const Ray ray{origin, (target - origin) * 0.5f};
    const auto hit = intersect(torus, ray, 0.0f, inf);
    if (!hit) continue;
    ++hits;
    const glm::vec3 p = ray.origin + hit->t * ray.direction;
    const float ring = std::sqrt(p.x * p.x + p.z * p.z) - 1.0f;
    EXPECT_NEAR(std::sqrt(ring * ring + p.y * p.y), 0.4f, 1e-4f);
    const glm::vec3 centre = glm::vec3(p.x, 0, p.z) / std::sqrt(p.x * p.x + p.z * p.z);
    expect_near(hit->normal, glm::normalize(p - centre), 1e-3f);
    EXPECT_NEAR(glm::length(hit->normal), 1.0f, 1e-5f);
  }
  EXPECT_GT(hits, 500);
}

TEST(Plane, HitsYZeroWithUpNormalAndXzUv) {
  const auto hit = intersect(Plane{}, Ray{{3, 2, -1}, {0, -1, 0}}, 0.0f, inf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.0f, 1e-6f);
  expect_near(hit->normal, {0, 1, 0});
  EXPECT_EQ(hit->uv, glm::vec2(3, -1));
  EXPECT_FALSE(intersect(Plane{}, Ray{{0, 2, 0}, {1, 0, 0}}, 0.0f, inf));
  EXPECT_FALSE(intersect(Plane{}, Ray{{0, 2, 0}, {0, 1, 0}}, 0.0f, inf));
}

TEST(Box, EachFaceGivesItsOutwardNormal) {
  const Box box{{1.0f, 2.0f, 3.0f}};
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      glm::vec3 origin(0.1f), direction(0.0f);
      origin[axis] = side * 10.0f;
      direction[axis] = -side;
      const auto hit = intersect(box, Ray{origin, direction}, 0.0f, inf);
      ASSERT_TRUE(hit);
      EXPECT_NEAR(hit->t, 10.0f - box.half_size[axis], 1e-5f);
      glm::vec3 normal(0.0f);
      normal[axis] = side;
      expect_near(hit->normal, normal);
      EXPECT_GE(hit->uv.x, 0.0f);
      EXPECT_LE(hit->uv.y, 1.0f);
    }
  EXPECT_FALSE(intersect(box, Ray{{5, 5, 5}, {1, 0, 0}}, 0.0f, inf));
  const auto inside = intersect(box, Ray{{0, 0, 0}, {0, 0, 1}}, 0.0f, inf);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(inside->t, 3.0f, 1e-6f);
}

TEST(Revolution, StraightVerticalProfileIsACylinder) {
  const Revolution cylinder({{0.5f, -1.0f}, {0.5f, 1.0f}});
  const auto hit = intersect(cylinder, Ray{{3, 0.3f, 0}, {-1, 0, 0}}, 0.0f, inf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 2.5f, 1e-5f);
  expect_near(hit->normal, {1, 0, 0}, 1e-5f);
  EXPECT_NEAR(cylinder.point_at(hit->uv.y).y, 0.3f, 1e-3f) << "v is the profile parameter of the hit";
  // Open ends: a ray down the axis misses; one inside the tube sees the inside wall.
  EXPECT_FALSE(intersect(cylinder, Ray{{0, 5, 0}, {0, -1, 0}}, 0.0f, inf));
  const auto inner = intersect(cylinder, Ray{{0, 0, 0}, {0, 0, 2}}, 0.0f, inf);
  ASSERT_TRUE(inner);
  EXPECT_NEAR(inner->t, 0.25f, 1e-5f);
  expect_near(inner->normal, {0, 0, 1}, 1e-5f);
}

TEST(Revolution, ConeProfileMatchesTheConesClosedForm) {
  // radius = 1 - height/2 from (1, 0) to (0, 2); Catmull-Rom through two
  // points with doubled ends is the straight line.
  const Revolution cone({{1.0f, 0.0f}, {0.0f, 2.0f}});
  const float height = 0.8f;
  const auto hit = intersect(cone, Ray{{0, height, 4}, {0, 0, -1}}, 0.0f, inf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 4.0f - (1.0f - height / 2.0f), 1e-3f);
  expect_near(hit->normal, glm::normalize(glm::vec3(0, 1, 2)), 1e-3f);  // (dh, -dr) = (2, 1) -> radial 2, up 1
}

TEST(Revolution, RandomHitsLieOnTheProfile) {
  const Revolution vase({{0.0f, -1.0f}, {0.6f, -1.0f}, {0.9f, 0.0f}, {0.4f, 0.8f}, {0.5f, 1.2f}});
  std::mt19937 random(1989);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 origin = glm::normalize(glm::vec3(unit(random), unit(random), unit(random))) * 5.0f;
    const glm::vec3 target(unit(random) * 0.5f, unit(random), unit(random) * 0.5f);
    const auto hit = intersect(vase, Ray{origin, target - origin}, 0.0f, inf);
    if (!hit) continue;
    ++hits;
    const glm::vec3 p = origin + hit->t * (target - origin);
    // The hit's profile parameter names the spline point at the hit's
    // radius and height, within the tessellation's error.
    const glm::vec2 on_profile = vase.point_at(hit->uv.y);
    EXPECT_NEAR(std::sqrt(p.x * p.x + p.z * p.z), on_profile.x, 2e-3f);
    EXPECT_NEAR(p.y, on_profile.y, 2e-3f);
    EXPECT_NEAR(glm::length(hit->normal), 1.0f, 1e-5f);
  }
  EXPECT_GT(hits, 100);
}

// Slabs against closed forms: a ray down -z from z = 5 enters the box
// [-1, 1]^3 at t = 4 through z = 1 and leaves at t = 6.
TEST(ClipToBox, EntryAndExitOfAnAxisRay) {
  const std::optional<Span> span =
      clip_to_box(Ray{{0.2f, -0.3f, 5.0f}, {0.0f, 0.0f, -1.0f}}, glm::vec3(-1.0f), glm::vec3(1.0f));
  ASSERT_TRUE(span);
  EXPECT_FLOAT_EQ(span->near, 4.0f);
  EXPECT_FLOAT_EQ(span->far, 6.0f);
  EXPECT_EQ(span->near_axis, 2);
  EXPECT_EQ(span->far_axis, 2);
}

// A diagonal ray through the corner region: it enters through x = -1 at
// t = 1 and leaves through y = 2 at t = 2 (x = 0 then).
TEST(ClipToBox, DiagonalRayEntersAndLeavesThroughDifferentFaces) {
  const std::optional<Span> span =
      clip_to_box(Ray{{-2.0f, 0.0f, 0.5f}, {1.0f, 1.0f, 0.0f}}, glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(1.0f, 2.0f, 1.0f));
  ASSERT_TRUE(span);
  EXPECT_FLOAT_EQ(span->near, 1.0f);
  EXPECT_EQ(span->near_axis, 0);
  EXPECT_FLOAT_EQ(span->far, 2.0f);
  EXPECT_EQ(span->far_axis, 1);
}

TEST(ClipToBox, MissesAndParallelRays) {
  EXPECT_FALSE(clip_to_box(Ray{{3.0f, 3.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, glm::vec3(-1.0f), glm::vec3(1.0f)));
  // Parallel to x and z, outside the y slab.
  EXPECT_FALSE(clip_to_box(Ray{{0.0f, 1.5f, 5.0f}, {0.0f, 0.0f, -1.0f}}, glm::vec3(-1.0f), glm::vec3(1.0f)));
  // From inside: the entry lies behind the origin.
  const std::optional<Span> inside = clip_to_box(Ray{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}, glm::vec3(-1.0f), glm::vec3(1.0f));
  ASSERT_TRUE(inside);
  EXPECT_FLOAT_EQ(inside->near, -1.0f);
  EXPECT_FLOAT_EQ(inside->far, 1.0f);
}

}  // namespace
}  // namespace shadetree
