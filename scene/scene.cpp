#include "scene/scene.h"

#include <cmath>
#include <map>
#include <memory>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_intersector.h"
#include "io/resource_path.h"

namespace shadetree {
namespace {

glm::vec3 to_vec3(const std::array<float, 3>& value) { return {value[0], value[1], value[2]}; }

Shape analytic_shape(const ObjectDesc& desc) {
  switch (desc.type) {
    case ObjectType::sphere: return Sphere{desc.radius};
    case ObjectType::torus: return Torus{desc.major_radius, desc.minor_radius};
    case ObjectType::plane: return Plane{};
    case ObjectType::box: return Box{to_vec3(desc.half_size)};
    case ObjectType::revolution: {
      std::vector<glm::vec2> profile;
      for (const auto& point : desc.profile) profile.emplace_back(point[0], point[1]);
      return Revolution(std::move(profile));
    }
    case ObjectType::mesh: break;
  }
  return Sphere{};
}

}  // namespace

glm::mat4 object_to_world(const TransformDesc& transform) {
  glm::mat4 matrix = glm::translate(glm::mat4(1.0f), to_vec3(transform.translate));
  matrix = glm::rotate(matrix, glm::radians(transform.rotate_degrees[2]), glm::vec3(0, 0, 1));
  matrix = glm::rotate(matrix, glm::radians(transform.rotate_degrees[1]), glm::vec3(0, 1, 0));
  matrix = glm::rotate(matrix, glm::radians(transform.rotate_degrees[0]), glm::vec3(1, 0, 0));
  return glm::scale(matrix, to_vec3(transform.scale));
}

Result<Scene> Scene::build(const SceneDesc& desc, const std::string& graph_file,
                           const std::vector<std::string>& search_paths) {
  Scene scene;
  scene.desc_ = desc;
  std::map<std::string, std::shared_ptr<const MeshIntersector>> meshes;  // each file read once
  for (std::size_t index = 0; index < desc.objects.size(); ++index) {
    const ObjectDesc& object_desc = desc.objects[index];
    SceneObject object;
    object.id = object_desc.id;
    object.color = to_vec3(object_desc.color);
    if (object_desc.type == ObjectType::mesh) {
      Result<std::string> path = resolve_graph_resource(graph_file, object_desc.mesh_file, search_paths,
                                                        "scene object #" + std::to_string(index + 1) + " file");
      if (!path) return path.error();
      std::shared_ptr<const MeshIntersector>& mesh = meshes[*path];
      if (!mesh) {
        Result<TriangleMesh> loaded = load_mesh(*path);
        if (!loaded) return loaded.error();
        mesh = std::make_shared<const MeshIntersector>(std::move(*loaded));
      }
      object.shape = MeshShape{mesh};
    } else {
      object.shape = analytic_shape(object_desc);
    }
    object.object_to_world = object_to_world(object_desc.transform);
    object.world_to_object = glm::inverse(object.object_to_world);
    object.normal_to_world = glm::inverseTranspose(glm::mat3(object.object_to_world));
    object.normal_to_object = glm::inverse(object.normal_to_world);
    scene.objects_.push_back(std::move(object));
  }
  for (const LightDesc& light_desc : desc.lights) {
    Light light;
    light.type = light_desc.type;
    light.direction = glm::normalize(to_vec3(light_desc.direction));
    light.position = to_vec3(light_desc.position);
    light.radiance = to_vec3(light_desc.color) * light_desc.intensity;
    scene.lights_.push_back(light);
  }
  return scene;
}

std::optional<SceneHit> Scene::intersect(const Ray& ray, float t_min, float t_max) const {
  std::optional<SceneHit> nearest;
  for (const SceneObject& object : objects_) {
    const Ray local{glm::vec3(object.world_to_object * glm::vec4(ray.origin, 1.0f)),
                    glm::vec3(object.world_to_object * glm::vec4(ray.direction, 0.0f))};
    std::optional<SurfaceHit> hit = shadetree::intersect(object.shape, local, t_min, t_max);
    if (!hit) continue;
    t_max = hit->t;
    SceneHit& result = nearest.emplace();
    result.object = &object;
    result.t = hit->t;
    result.object_point = local.origin + hit->t * local.direction;
    result.object_normal = hit->normal;
    result.world_point = ray.origin + hit->t * ray.direction;
    result.world_normal = glm::normalize(object.normal_to_world * hit->normal);
    result.uv = hit->uv;
  }
  return nearest;
}

bool Scene::occluded(const Ray& ray, float t_min, float t_max) const {
  for (const SceneObject& object : objects_) {
    const Ray local{glm::vec3(object.world_to_object * glm::vec4(ray.origin, 1.0f)),
                    glm::vec3(object.world_to_object * glm::vec4(ray.direction, 0.0f))};
    if (shadetree::intersect(object.shape, local, t_min, t_max)) return true;
  }
  return false;
}

}  // namespace shadetree
