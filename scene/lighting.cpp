#include "scene/lighting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace shadetree {

glm::vec3 direction_to_light(const Light& light, const glm::vec3& point, float* distance) {
  if (light.type == LightType::directional) {
    *distance = std::numeric_limits<float>::infinity();
    return -light.direction;
  }
  const glm::vec3 offset = light.position - point;
  *distance = glm::length(offset);
  return *distance > 0.0f ? offset / *distance : glm::vec3(0.0f, 1.0f, 0.0f);
}

LightSeen light_seen(const Light& light, const glm::vec3& point, const glm::vec3& to_viewer) {
  LightSeen seen;
  seen.toward = direction_to_light(light, point, &seen.distance);
  seen.half = glm::normalize(seen.toward + to_viewer);
  return seen;
}

glm::vec3 light_point(const Scene& scene, const SurfaceMaterial& material, const LitPoint& point, bool shadows,
                      const float* light_transmittance, const LightSeen* seen) {
  glm::vec3 result = glm::vec3(scene.desc().ambient[0], scene.desc().ambient[1], scene.desc().ambient[2]) *
                         material.color +
                     material.emission;
  const float exponent = specular_exponent(material.roughness);
  const bool objects_shadow = shadows && !scene.objects().empty();
  const auto libm_power = [](float base, float power) { return std::pow(base, power); };
  for (std::size_t index = 0; index < scene.lights().size(); ++index) {
    const Light& light = scene.lights()[index];
    const LightSeen here = seen ? seen[index] : light_seen(light, point.point, point.to_viewer);
    if (!lit_by(point.shading_normal, point.geometric_normal, here)) continue;
    // Shadow rays start off the surface by an amount that scales with the
    // point's distance from the origin (float spacing grows with it).
    if (objects_shadow &&
        scene.occluded(Ray{point.point + 1e-4f * (1.0f + glm::length(point.point)) * point.geometric_normal,
                           here.toward},
                       0.0f, here.distance))
      continue;
    add_light_term(material, point.shading_normal, here, exponent, libm_power,
                   (light_transmittance ? light_transmittance[index] : 1.0f) * light.radiance, result);
  }
  return result;
}

}  // namespace shadetree
