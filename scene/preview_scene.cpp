#include "scene/preview_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "io/mesh_file.h"

namespace shadetree {
namespace {

// A camera looking at the origin from `direction`, far enough for a
// sphere of `radius` to fill most of the frame.
CameraDesc framing(float radius, std::array<float, 3> direction) {
  CameraDesc camera;
  camera.fov_degrees = 30.0f;
  const float length =
      std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  const float distance = 1.15f * radius / std::sin(camera.fov_degrees * 3.14159265f / 360.0f);
  for (int axis = 0; axis < 3; ++axis) camera.position[axis] = direction[axis] / length * distance;
  return camera;
}

}  // namespace

Result<SceneDesc> preview_scene(const std::string& object) {
  SceneDesc scene;
  scene.lights = default_lights();
  ObjectDesc shape;
  if (object == "sphere") {
    shape.type = ObjectType::sphere;
    scene.camera = framing(1.0f, {0.0f, 0.35f, 1.0f});
  } else if (object == "torus") {
    shape.type = ObjectType::torus;
    scene.camera = framing(shape.major_radius + shape.minor_radius, {0.0f, 0.9f, 1.0f});
  } else if (object == "box") {
    shape.type = ObjectType::box;
    shape.transform.rotate_degrees = {0.0f, 35.0f, 0.0f};
    scene.camera = framing(std::sqrt(3.0f), {0.0f, 0.6f, 1.0f});
  } else if (object == "plane") {
    // A floor receding to the horizon, as the 1992 checkerboard.
    shape.type = ObjectType::plane;
    scene.camera.position = {0.0f, 1.0f, 4.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fov_degrees = 50.0f;
  } else {
    Result<TriangleMesh> mesh = load_mesh(object);
    if (!mesh) return mesh.error();
    const auto [low, high] = mesh_bounds(*mesh);
    if (std::string problem = too_small_to_scale(low, high, "a preview object"); !problem.empty())
      return Diagnostic{ExitStatus::invalid_input, object, {}, {}, problem};
    const glm::vec3 centre = (low + high) * 0.5f;
    const float radius = glm::length(high - low) * 0.5f;
    shape.type = ObjectType::mesh;
    shape.mesh_file = std::filesystem::absolute(object).string();
    shape.transform.scale = {1.0f / radius, 1.0f / radius, 1.0f / radius};
    shape.transform.translate = {-centre.x / radius, -centre.y / radius, -centre.z / radius};
    scene.camera = framing(1.0f, {0.0f, 0.35f, 1.0f});
  }
  scene.objects.push_back(shape);
  return scene;
}

Result<SceneDesc> surface_scene_desc(const Graph& graph) {
  if (graph.render.scene) return *graph.render.scene;
  return preview_scene("sphere");
}

}  // namespace shadetree
