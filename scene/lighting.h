// The driver's lighting of a shaded surface point: Lambert diffuse plus a
// Blinn-Phong specular lobe from each light, with shadow rays, after the
// graph has given the point's colour, perturbed normal and material
// (Perlin 1985 runs the shade program first and lights its outputs; so do
// Rhoades et al. 1992 with deferred shading).
#pragma once

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace shadetree {

// What a surface graph says about one visible point.
struct SurfaceMaterial {
  glm::vec3 color{0.8f};
  float specular = 0.25f;   // defaults where the graph has no such output
  float roughness = 0.35f;
  glm::vec3 emission{0.0f};
};

struct LitPoint {
  glm::vec3 point{0.0f};             // world
  glm::vec3 shading_normal{0.0f};    // world, unit, toward the viewer
  glm::vec3 geometric_normal{0.0f};  // world, unit, toward the viewer
  glm::vec3 to_viewer{0.0f};         // world, unit
};

// A light as a point sees it: the unit direction toward it, its distance
// (infinite for a directional light) and the Blinn-Phong half vector
// between it and the viewer. A directional light seen along one view
// direction looks the same from every point, so the samples of a volume
// ray share one.
struct LightSeen {
  glm::vec3 toward{0.0f};
  float distance = 0.0f;
  glm::vec3 half{0.0f};
};

LightSeen light_seen(const Light& light, const glm::vec3& point, const glm::vec3& to_viewer);

// Blinn-Phong exponent of a roughness in [0, 1] (2 / r^2 - 2, the
// exponent whose lobe matches a Beckmann distribution of slope r).
inline float specular_exponent(float roughness) {
  const float r = std::clamp(roughness, 0.02f, 1.0f);
  return 2.0f / (r * r) - 2.0f;
}

// Whether light arriving from unit direction `toward_light` reaches a
// surface of normal `normal` (not from behind it): light_point passes
// over a light that does not, so no shadow need be found toward it.
inline bool reaches(const glm::vec3& normal, const glm::vec3& toward_light) {
  return !(glm::dot(normal, toward_light) <= 0.0f);
}

// Whether a light seen as `here` lights a point of shading normal
// `normal` and geometric normal `geometric_normal`: not from behind either
// (a light behind the geometric surface cannot reach it, whatever the
// perturbed normal says).
inline bool lit_by(const glm::vec3& normal, const glm::vec3& geometric_normal, const LightSeen& here) {
  return reaches(normal, here.toward) && reaches(geometric_normal, here.toward);
}

// Adds to `result` what one light that the point is `lit_by`, seen from it as
// `here`, adds: `radiance` (the light's, times what reaches the point of
// it) times color N.L + specular max(0, N.H)^exponent (Blinn-Phong), the
// power taken by `power(base, exponent)`. A component at a time: the
// volume marcher adds every shaded sample's lights, and GCC's pairs of
// components there (one 8-byte load) waited for the stores of single ones.
template <class Power>
void add_light_term(const SurfaceMaterial& material, const glm::vec3& normal, const LightSeen& here, float exponent,
                    Power power, const glm::vec3& radiance, glm::vec3& result) {
  const float toward = glm::dot(normal, here.toward);
  // A half vector at or past 90 degrees (or NaN) adds pow(0, exponent),
  // +0 but for the exponent 0 of roughness 1, which changes no term: the
  // power is not taken for it.
  const float facing = std::max(0.0f, glm::dot(normal, here.half));
  const float specular =
      material.specular != 0.0f && (facing > 0.0f || exponent == 0.0f) ? material.specular * power(facing, exponent) : 0.0f;
  for (int c = 0; c < 3; ++c) result[c] += radiance[c] * (material.color[c] * toward + specular);
}

// ambient * color + emission + the sum over lights of
// radiance * (color * max(0, N.L) + specular * max(0, N.H)^exponent),
// each light's term dropped where a shadow ray finds an object first, and
// multiplied by light_transmittance[i] where given (the fraction of light
// i that reaches the point through a volume). `seen` holds each light as
// the point sees it, where the caller has it (light_seen).
glm::vec3 light_point(const Scene& scene, const SurfaceMaterial& material, const LitPoint& point, bool shadows,
                      const float* light_transmittance = nullptr, const LightSeen* seen = nullptr);

// Unit direction from `point` toward `light`, and the distance to it
// (infinite for directional lights).
glm::vec3 direction_to_light(const Light& light, const glm::vec3& point, float* distance);

}  // namespace shadetree
