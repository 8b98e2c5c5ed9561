// A scene ready to trace: objects with their shapes and transforms, and
// lights, built from a SceneDesc. Shapes live in object space; the scene
// carries world rays into each object's space and hits back out, so that
// a solid texture evaluated at the object-space point sticks to its
// object however it is moved (Perlin 1985: "shape and texture become
// independent").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "graph/diagnostic.h"
#include "graph/scene.h"
#include "scene/shapes.h"

namespace shadetree {

struct SceneObject {
  int id = 0;
  Shape shape;
  glm::mat4 object_to_world{1.0f};
  glm::mat4 world_to_object{1.0f};
  glm::mat3 normal_to_world{1.0f};   // inverse transpose of the linear part
  glm::mat3 normal_to_object{1.0f};  // its inverse
  glm::vec3 color{0.8f};             // a volume scene's opaque objects are this colour
};

struct Light {
  LightType type = LightType::directional;
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // directional: unit, the way the light travels
  glm::vec3 position{0.0f};                // point
  glm::vec3 radiance{1.0f};                // colour times intensity
};

// A world ray's nearest hit.
struct SceneHit {
  const SceneObject* object = nullptr;
  float t = 0.0f;
  glm::vec3 world_point{0.0f};
  glm::vec3 world_normal{0.0f};   // unit, out of the solid
  glm::vec3 object_point{0.0f};
  glm::vec3 object_normal{0.0f};  // unit, out of the solid
  glm::vec2 uv{0.0f};
};

class Scene {
 public:
  // Mesh files are resolved against `graph_file`'s folder and
  // `search_paths` (resource_path.h) and read once each.
  static Result<Scene> build(const SceneDesc& desc, const std::string& graph_file,
                             const std::vector<std::string>& search_paths);

  std::optional<SceneHit> intersect(const Ray& ray, float t_min, float t_max) const;
  // Whether anything lies on the ray with t in (t_min, t_max).
  bool occluded(const Ray& ray, float t_min, float t_max) const;

  const std::vector<SceneObject>& objects() const { return objects_; }
  const std::vector<Light>& lights() const { return lights_; }
  const SceneDesc& desc() const { return desc_; }

 private:
  SceneDesc desc_;
  std::vector<SceneObject> objects_;
  std::vector<Light> lights_;
};

// The transform a TransformDesc describes: scale, rotate x, y, z, translate.
glm::mat4 object_to_world(const TransformDesc& transform);

}  // namespace shadetree
