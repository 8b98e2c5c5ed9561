// A light's transmittance grid against closed forms: a uniform medium
// lets through (1 - opacity)^(path / reference step) along the light, for
// parallel and for fanning light rays, and an opaque slab's sharp shadow
// edge is left to shadow rays.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "render/transmittance_grid.h"

namespace shadetree {
namespace {

constexpr float opacity = 0.2f;
constexpr float reference_step = 0.1f;

TransmittanceGridSpec spec(float spacing) {
  TransmittanceGridSpec result;
  result.spacing = spacing;
  result.shadow_step = 0.05f;
  result.reference_step = reference_step;
  result.termination = 0.0f;
  result.max_values = std::size_t{1} << 22;
  result.threads = 2;
  return result;
}

// Opacity `opacity` everywhere in the bounds.
void uniform(const std::vector<glm::vec3>&, const std::vector<glm::vec3>&, std::vector<float>& opacities) {
  std::fill(opacities.begin(), opacities.end(), opacity);
}

float through(float path) { return std::pow(1.0f - opacity, path / reference_step); }

TEST(TransmittanceGrid, AUniformMediumUnderTheSunGivesTheClosedForm) {
  Light sun;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const glm::vec3 lo(-1.0f), hi(1.0f);
  Result<std::optional<TransmittanceGrid>> grid = TransmittanceGrid::build(sun, lo, hi, spec(0.1f), uniform);
  ASSERT_TRUE(grid.ok());
  ASSERT_TRUE(grid->has_value());
  for (const glm::vec3& x : {glm::vec3(0.0f), glm::vec3(0.5f, -0.8f, 0.1f), glm::vec3(-0.7f, 0.9f, -0.3f)}) {
    // The path from x toward the sun to where it leaves the cube.
    float path = std::numeric_limits<float>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      const float d = -sun.direction[axis];
      if (d != 0.0f) path = std::min(path, ((d > 0.0f ? hi[axis] : lo[axis]) - x[axis]) / d);
    }
    const float looked_up = (*grid)->at(x);
    ASSERT_NE(looked_up, TransmittanceGrid::edge);
    EXPECT_NEAR(looked_up, through(path), 2e-3f * through(path)) << x.x << " " << x.y << " " << x.z;
  }
  // Beside the cube, as seen from the sun, the light is whole; below it,
  // it has crossed the whole cube, here from its top face to its bottom.
  EXPECT_EQ((*grid)->at(glm::vec3(5.0f, 0.0f, 0.0f)), 1.0f);
  const glm::vec3 below = glm::vec3(0.0f) + 3.0f * sun.direction;
  EXPECT_NEAR((*grid)->at(below), through(2.0f / -sun.direction.y), 1e-3f);
}

TEST(TransmittanceGrid, APointLightsRaysFanOutFromIt) {
  Light bulb;
  bulb.type = LightType::point;
  bulb.position = {0.0f, 4.0f, 0.0f};
  Result<std::optional<TransmittanceGrid>> grid =
      TransmittanceGrid::build(bulb, glm::vec3(-1.0f), glm::vec3(1.0f), spec(0.05f), uniform);
  ASSERT_TRUE(grid.ok());
  ASSERT_TRUE(grid->has_value());
  // Straight below the light the path is the depth below the top face;
  // off the axis it is longer by the slant.
  EXPECT_NEAR((*grid)->at(glm::vec3(0.0f, -0.5f, 0.0f)), through(1.5f), 2e-3f);
  const glm::vec3 x(0.6f, 0.0f, 0.0f);
  const float slant = glm::length(x - bulb.position) / (bulb.position.y - x.y);
  EXPECT_NEAR((*grid)->at(x), through(1.0f * slant), 2e-3f);
  // A light among the bounds has no grid: its rays are marched.
  bulb.position = {0.0f, 0.5f, 0.0f};
  Result<std::optional<TransmittanceGrid>> inside =
      TransmittanceGrid::build(bulb, glm::vec3(-1.0f), glm::vec3(1.0f), spec(0.05f), uniform);
  ASSERT_TRUE(inside.ok());
  EXPECT_FALSE(inside->has_value());
}

// An opaque slab (x < 0) under a light from straight above: its shadow's
// edge, x = 0, passes between two light rays, where the grid answers
// nothing; elsewhere it answers exactly, dark or lit, never a blur.
TEST(TransmittanceGrid, AHardShadowsEdgeIsLeftToShadowRays) {
  Light sun;
  sun.direction = {0.0f, -1.0f, 0.0f};
  const auto slab = [](const std::vector<glm::vec3>& points, const std::vector<glm::vec3>&,
                       std::vector<float>& opacities) {
    for (std::size_t i = 0; i < points.size(); ++i)
      opacities[i] = points[i].x < 0.0f && points[i].y > 0.5f ? 1.0f : 0.0f;
  };
  TransmittanceGridSpec settings = spec(0.1f);
  settings.termination = 1.0f / 512.0f;
  Result<std::optional<TransmittanceGrid>> grid =
      TransmittanceGrid::build(sun, glm::vec3(-1.0f), glm::vec3(1.0f), settings, slab);
  ASSERT_TRUE(grid.ok() && grid->has_value());
  int unanswered = 0;
  for (float x = -0.3f; x <= 0.3f; x += 0.005f) {
    const float looked_up = (*grid)->at(glm::vec3(x, 0.0f, 0.0f));
    if (looked_up == TransmittanceGrid::edge) {
      ++unanswered;
      EXPECT_LT(std::fabs(x), 0.1f) << "only between the two rays about the edge";
      continue;
    }
    EXPECT_EQ(looked_up, x < 0.0f ? 0.0f : 1.0f) << x;
  }
  EXPECT_GT(unanswered, 0);
}

// Only the depths a light ray gains are kept: under the sun an opaque
// slab spends every ray that meets it at its first sample, and the others
// gain nothing, so each of the 21 x 21 rays (2 units at 0.1) keeps at most
// one value (framed by the 0 before it and the last after it), where a
// dense grid held 41 (2 units at 0.05, and the last).
TEST(TransmittanceGrid, AHardSurfaceKeepsOneDepthPerLightRay) {
  Light sun;
  sun.direction = {0.0f, -1.0f, 0.0f};
  const auto slab = [](const std::vector<glm::vec3>& points, const std::vector<glm::vec3>&,
                       std::vector<float>& opacities) {
    for (std::size_t i = 0; i < points.size(); ++i) opacities[i] = points[i].x < 0.0f ? 1.0f : 0.0f;
  };
  TransmittanceGridSpec settings = spec(0.1f);
  settings.termination = 1.0f / 512.0f;
  Result<std::optional<TransmittanceGrid>> grid =
      TransmittanceGrid::build(sun, glm::vec3(-1.0f), glm::vec3(1.0f), settings, slab);
  ASSERT_TRUE(grid.ok() && grid->has_value());
  constexpr std::size_t rays = 21 * 21;
  EXPECT_LE((*grid)->bytes(), rays * (sizeof(TransmittanceGrid::Row) + 3 * sizeof(float)));
  EXPECT_GT((*grid)->bytes(), rays * sizeof(TransmittanceGrid::Row));
  for (float y : {0.9f, 0.0f, -0.9f}) {
    EXPECT_EQ((*grid)->at(glm::vec3(-0.5f, y, 0.3f)), 0.0f) << y;
    EXPECT_EQ((*grid)->at(glm::vec3(0.5f, y, 0.3f)), 1.0f) << y;
  }
}

TEST(TransmittanceGrid, ItsSizeIsBounded) {
  Light sun;
  TransmittanceGridSpec settings = spec(1e-4f);
  settings.max_values = 100000;
  Result<std::optional<TransmittanceGrid>> grid =
      TransmittanceGrid::build(sun, glm::vec3(-1.0f), glm::vec3(1.0f), settings, uniform);
  ASSERT_TRUE(grid.ok() && grid->has_value());
  EXPECT_LE((*grid)->bytes(), 100000 * sizeof(float));
  EXPECT_GT((*grid)->spacing(), 1e-4f);
}

}  // namespace
}  // namespace shadetree
