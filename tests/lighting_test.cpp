// The drivers' lighting (scene/lighting.h): Lambert diffuse plus a
// Blinn-Phong lobe a light, against closed forms.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "scene/lighting.h"
#include "scene/scene.h"

namespace shadetree {
namespace {

// One white directional light travelling along `direction` (by default
// down -z), no ambient light.
Scene one_light(std::array<float, 3> direction = {0.0f, 0.0f, -1.0f}) {
  SceneDesc desc;
  desc.ambient = {0.0f, 0.0f, 0.0f};
  LightDesc sun;
  sun.direction = direction;
  desc.lights = {sun};
  Result<Scene> scene = Scene::build(desc, "lighting.json", {});
  EXPECT_TRUE(scene.ok()) << scene.error().to_string();
  return std::move(*scene);
}

// A point facing +z, seen from the direction `to_viewer`.
LitPoint facing_z(const glm::vec3& to_viewer) {
  LitPoint point;
  point.shading_normal = point.geometric_normal = {0.0f, 0.0f, 1.0f};
  point.to_viewer = glm::normalize(to_viewer);
  return point;
}

TEST(Lighting, AHeadOnLightGivesTheColourAndTheWholeLobe) {
  const Scene scene = one_light();
  SurfaceMaterial material;
  material.color = {0.2f, 0.4f, 0.6f};
  material.specular = 0.25f;
  // Seen from the light's side the half vector is the normal: N.H = 1.
  const glm::vec3 lit = light_point(scene, material, facing_z({0.0f, 0.0f, 1.0f}), false);
  EXPECT_FLOAT_EQ(lit.x, 0.2f + 0.25f);
  EXPECT_FLOAT_EQ(lit.z, 0.6f + 0.25f);
}

// The lobe is max(0, N.H)^exponent, 2 / r^2 - 2 for roughness r: at
// roughness 1 the exponent is 0 and the lobe is 1 everywhere the light
// reaches, even where the half vector is past 90 degrees from the normal
// (a grazing light, a viewer below the surface's plane); at 0.35 it is 0
// there.
TEST(Lighting, TheLobeBeyondNinetyDegreesIsZeroButAtRoughnessOne) {
  const Scene scene = one_light({-1.0f, 0.0f, -0.2f});
  const LitPoint grazing = facing_z({-1.0f, 0.0f, -0.5f});
  const glm::vec3 toward_light = glm::normalize(glm::vec3(1.0f, 0.0f, 0.2f));
  ASSERT_LT(glm::dot(grazing.shading_normal, glm::normalize(toward_light + grazing.to_viewer)), 0.0f);
  SurfaceMaterial material;
  material.color = glm::vec3(0.0f);
  material.specular = 0.5f;
  material.roughness = 0.35f;
  EXPECT_EQ(light_point(scene, material, grazing, false), glm::vec3(0.0f));
  material.roughness = 1.0f;
  EXPECT_FLOAT_EQ(specular_exponent(1.0f), 0.0f);
  EXPECT_EQ(light_point(scene, material, grazing, false), glm::vec3(0.5f));
}

// What reaches the point through a volume scales the light's whole term.
TEST(Lighting, TransmittanceScalesALightsTerm) {
  const Scene scene = one_light();
  SurfaceMaterial material;
  material.color = glm::vec3(0.5f);
  material.specular = 0.0f;
  const LitPoint point = facing_z({1.0f, 0.0f, 1.0f});
  const float transmittance = 0.3f;
  EXPECT_FLOAT_EQ(light_point(scene, material, point, true, &transmittance).y, 0.3f * 0.5f);
}

}  // namespace
}  // namespace shadetree
