// Rays and the hits the surface driver's visibility stage finds.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shadetree {

// origin + t * direction. The direction need not be unit length: a world
// ray carried into an object's space by the inverse of its transform keeps
// its parameter t, so hits in different objects compare by t.
struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};
};

// Where a ray meets a surface, in the space of the ray.
struct SurfaceHit {
  float t = 0.0f;
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit; out of the solid (shading normal for meshes with normals)
  glm::vec2 uv{0.0f};                  // the surface's own parameterization (see shapes.h, mesh.h)
};

}  // namespace shadetree
