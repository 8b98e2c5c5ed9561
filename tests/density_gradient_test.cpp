// The march's density gradient (render/density_gradient.h): from the
// previous sample and two probes off the ray, against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "nodes/semantics/soft_objects.h"
#include "render/density_gradient.h"

namespace shadetree {
namespace {

float soft_sphere_density(const glm::vec3& p) {
  return semantics::soft_sphere<float>({p.x, p.y, p.z}, {0.0f, 0.0f, 0.0f}, 1.0f, 0.8f);
}

TEST(RayFrame, IsOrthonormalForAnyDirection) {
  for (const glm::vec3 direction : {glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::normalize(glm::vec3(0.3f, -2, 0.7f))}) {
    const RayFrame frame = ray_frame(direction);
    EXPECT_NEAR(glm::length(frame.across_v), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(frame.across_w), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(frame.along, frame.across_v), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(frame.along, frame.across_w), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(frame.across_v, frame.across_w), 0.0f, 1e-6f);
  }
}

// A linear density is differentiated exactly, in any ray frame.
TEST(DensityGradient, IsExactForALinearDensity) {
  const glm::vec3 slope(0.5f, -2.0f, 1.25f);
  auto density = [&](const glm::vec3& p) { return glm::dot(slope, p) + 3.0f; };
  const glm::vec3 x(0.2f, 0.4f, -0.1f);
  const RayFrame frame = ray_frame(glm::normalize(glm::vec3(1.0f, 2.0f, -3.0f)));
  const float back = 0.05f, probe = 0.02f;
  const glm::vec3 gradient =
      density_gradient(frame, {density(x), density(x - back * frame.along), back, density(x + probe * frame.across_v),
                               density(x + probe * frame.across_w), probe});
  EXPECT_NEAR(gradient.x, slope.x, 1e-3f);
  EXPECT_NEAR(gradient.y, slope.y, 1e-3f);
  EXPECT_NEAR(gradient.z, slope.z, 1e-3f);
}

// In a soft sphere's shell the density falls outward, so the gradient
// points to the centre, wherever the ray comes from.
TEST(DensityGradient, OfASoftSpherePointsRadially) {
  const float step = 0.005f;
  for (const glm::vec3 x : {glm::vec3(0.9f, 0.0f, 0.0f), glm::vec3(0.3f, -0.6f, 0.55f), glm::vec3(-0.5f, 0.5f, -0.5f)})
    for (const glm::vec3 direction : {glm::vec3(0, 0, -1), glm::normalize(glm::vec3(1, 1, 0)), glm::normalize(-x)}) {
      const RayFrame frame = ray_frame(direction);
      const glm::vec3 gradient = density_gradient(
          frame, {soft_sphere_density(x), soft_sphere_density(x - step * frame.along), step,
                  soft_sphere_density(x + step * frame.across_v), soft_sphere_density(x + step * frame.across_w), step});
      EXPECT_GT(glm::dot(glm::normalize(gradient), -glm::normalize(x)), 0.999f) << x.x << " " << x.y << " " << x.z;
    }
}

}  // namespace
}  // namespace shadetree
