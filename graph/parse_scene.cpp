// Scenes are checked for shape here (fields, types, ranges), so that a
// typo fails before anything renders; files they name are opened by the
// driver, which knows the search path.
#include "graph/parse_scene.h"

#include <algorithm>
#include <cmath>

#include "graph/format_fields.h"

namespace shadetree {
namespace {

class SceneParser {
 public:
  SceneParser(const JsonReader& reader, GraphKind kind) : reader_(reader), kind_(kind) {}

  SceneDesc parse(const json& scene) const {
    if (!scene.is_object()) fail("render scene must be an object");
    check_format_fields(reader_, scene, scene_fields(kind_), kind_, "render scene");
    SceneDesc result;
    if (scene.contains("camera")) result.camera = camera(scene["camera"]);
    // A surface graph shades its objects; a volume graph's objects are
    // opaque, of one colour each, seen through and behind the volume.
    if (kind_ != GraphKind::volume || scene.contains("objects")) {
      if (!scene.contains("objects")) fail("render scene has no \"objects\"");
      const json& objects = scene["objects"];
      if (!objects.is_array() || (objects.empty() && kind_ != GraphKind::volume))
        fail("scene objects must be a non-empty array");
      if (objects.size() > max_scene_objects)
        fail("scene has more than " + std::to_string(max_scene_objects) + " objects");
      for (std::size_t index = 0; index < objects.size(); ++index)
        result.objects.push_back(object(objects[index], index));
    }
    if (scene.contains("lights")) {
      const json& lights = scene["lights"];
      if (!lights.is_array()) fail("scene lights must be an array");
      if (lights.size() > max_scene_lights) fail("scene has more than " + std::to_string(max_scene_lights) + " lights");
      for (std::size_t index = 0; index < lights.size(); ++index)
        result.lights.push_back(light(lights[index], "scene light #" + std::to_string(index + 1)));
    } else {
      result.lights = default_lights();
    }
    if (scene.contains("background")) result.background = color(scene["background"], "scene background");
    if (scene.contains("environment")) {
      result.environment = reader_.required_string(scene, "environment", {});
      if (result.environment.empty()) fail("scene environment must name an environment graph file");
    }
    if (scene.contains("ambient")) result.ambient = color(scene["ambient"], "scene ambient");
    if (scene.contains("lighting")) {
      const json& lighting = scene["lighting"];
      if (lighting == "lit") result.lighting = Lighting::lit;
      else if (lighting == "none") result.lighting = Lighting::none;
      else fail("scene lighting must be \"lit\" or \"none\", got " + lighting.dump());
    }
    if (scene.contains("shadows")) {
      if (!scene["shadows"].is_boolean()) fail("scene shadows must be true or false");
      result.shadows = scene["shadows"].get<bool>();
    }
    return result;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { reader_.fail({}, {}, message); }

  float number(const json& value, const std::string& what) const { return reader_.number(value, {}, what); }

  float positive(const json& value, const std::string& what) const {
    const float result = number(value, what);
    if (!(result > 0.0f)) fail(what + " must be positive");
    return result;
  }

  std::array<float, 3> vec3(const json& value, const std::string& what) const {
    std::vector<float> values = reader_.numbers(value, {}, what);
    if (values.size() != 3) fail(what + " must be [x, y, z]");
    return {values[0], values[1], values[2]};
  }

  std::array<float, 3> color(const json& value, const std::string& what) const {
    std::vector<float> values = reader_.numbers(value, {}, what);
    if (values.size() == 1) values.assign(3, values[0]);
    if (values.size() != 3) fail(what + " must be a number or [r, g, b]");
    for (float value : values)
      if (value < 0.0f) fail(what + " must not be negative");
    return {values[0], values[1], values[2]};
  }

  CameraDesc camera(const json& spec) const {
    if (!spec.is_object()) fail("scene camera must be an object");
    check_format_fields(reader_, spec, camera_fields(), kind_, "scene camera");
    CameraDesc camera;
    if (spec.contains("position")) camera.position = vec3(spec["position"], "camera position");
    if (spec.contains("target")) camera.target = vec3(spec["target"], "camera target");
    if (spec.contains("up")) camera.up = vec3(spec["up"], "camera up");
    if (spec.contains("fov")) {
      camera.fov_degrees = number(spec["fov"], "camera fov");
      if (!(camera.fov_degrees > 0.0f && camera.fov_degrees < 180.0f))
        fail("camera fov must be between 0 and 180 degrees");
    }
    if (spec.contains("orthographic")) {
      camera.orthographic = true;
      camera.orthographic_height = positive(spec["orthographic"], "camera orthographic height");
    }
    const float dx = camera.target[0] - camera.position[0], dy = camera.target[1] - camera.position[1],
                dz = camera.target[2] - camera.position[2];
    const float distance = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (!(distance > 0.0f) || !std::isfinite(distance)) fail("camera position and target must differ");
    const auto& up = camera.up;
    const float cx = dy * up[2] - dz * up[1], cy = dz * up[0] - dx * up[2], cz = dx * up[1] - dy * up[0];
    const float up_length = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    if (!(std::sqrt(cx * cx + cy * cy + cz * cz) > 1e-6f * distance * up_length))
      fail("camera up must not be parallel to the view direction");
    return camera;
  }

  TransformDesc transform(const json& spec, const std::string& where) const {
    if (!spec.is_object()) fail(where + " transform must be an object of translate, rotate, scale");
    check_format_fields(reader_, spec, transform_fields(), kind_, where + " transform");
    TransformDesc result;
    if (spec.contains("translate")) result.translate = vec3(spec["translate"], where + " translate");
    if (spec.contains("rotate")) result.rotate_degrees = vec3(spec["rotate"], where + " rotate");
    if (spec.contains("scale")) {
      std::vector<float> values = reader_.numbers(spec["scale"], {}, where + " scale");
      if (values.size() == 1) values.assign(3, values[0]);
      if (values.size() != 3) fail(where + " scale must be a number or [x, y, z]");
      for (float value : values)
        if (!(std::fabs(value) > 1e-12f)) fail(where + " scale must not be zero");
      result.scale = {values[0], values[1], values[2]};
    }
    return result;
  }

  ObjectDesc object(const json& spec, std::size_t index) const {
    std::string where = "scene object #" + std::to_string(index + 1);
    if (!spec.is_object()) fail(where + " must be an object with a \"type\"");
    const std::string type = reader_.required_string(spec, "type", {});
    ObjectDesc object;
    object.id = static_cast<int>(index);
    if (std::find(scene_object_types.begin(), scene_object_types.end(), type) == scene_object_types.end())
      fail(where + " has unknown type \"" + type + "\" (sphere, torus, plane, box, revolution, mesh)");
    check_format_fields(reader_, spec, scene_object_fields(type), kind_, where + " (a " + type + ")");
    if (type == "sphere") {
      object.type = ObjectType::sphere;
      if (spec.contains("radius")) object.radius = positive(spec["radius"], where + " radius");
    } else if (type == "torus") {
      object.type = ObjectType::torus;
      if (spec.contains("major_radius")) object.major_radius = positive(spec["major_radius"], where + " major_radius");
      if (spec.contains("minor_radius")) object.minor_radius = positive(spec["minor_radius"], where + " minor_radius");
    } else if (type == "plane") {
      object.type = ObjectType::plane;
    } else if (type == "box") {
      object.type = ObjectType::box;
      if (spec.contains("size")) {
        std::array<float, 3> size = vec3(spec["size"], where + " size");
        for (int axis = 0; axis < 3; ++axis) {
          if (!(size[axis] > 0.0f)) fail(where + " size must be positive");
          object.half_size[axis] = size[axis] / 2.0f;
        }
      }
    } else if (type == "revolution") {
      object.type = ObjectType::revolution;
      if (!spec.contains("profile")) fail(where + " (a revolution) needs a \"profile\" of [radius, height] points");
      const json& profile = spec["profile"];
      if (!profile.is_array() || profile.size() < 2 || profile.size() > max_profile_points)
        fail(where + " profile must hold 2 to " + std::to_string(max_profile_points) + " [radius, height] points");
      for (const json& point : profile) {
        std::vector<float> values = reader_.numbers(point, {}, where + " profile point");
        if (values.size() != 2 || values[0] < 0.0f)
          fail(where + " profile points must be [radius, height] with radius >= 0");
        object.profile.push_back({values[0], values[1]});
      }
    } else if (type == "mesh") {
      object.type = ObjectType::mesh;
      object.mesh_file = reader_.required_string(spec, "file", {});
      if (object.mesh_file.empty()) fail(where + " file must not be empty");
    }
    if (spec.contains("id")) {
      const json& id = spec["id"];
      if (!id.is_number_integer() || id.get<double>() < 0 || id.get<double>() > 1e6)
        fail(where + " id must be an integer from 0 to 1000000");
      object.id = id.get<int>();
    }
    if (spec.contains("transform")) object.transform = transform(spec["transform"], where);
    if (spec.contains("color")) object.color = color(spec["color"], where + " color");
    return object;
  }

  LightDesc light(const json& spec, const std::string& where) const {
    if (!spec.is_object()) fail(where + " must be an object with a \"type\"");
    const std::string type = reader_.required_string(spec, "type", {});
    LightDesc light;
    if (std::find(scene_light_types.begin(), scene_light_types.end(), type) == scene_light_types.end())
      fail(where + " has unknown type \"" + type + "\" (directional, point)");
    check_format_fields(reader_, spec, scene_light_fields(type), kind_, where);
    if (type == "directional") {
      light.type = LightType::directional;
      if (spec.contains("direction")) light.direction = vec3(spec["direction"], where + " direction");
      const auto& d = light.direction;
      if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 0.0f)) fail(where + " direction must not be zero");
    } else {
      light.type = LightType::point;
      if (spec.contains("position")) light.position = vec3(spec["position"], where + " position");
    }
    if (spec.contains("color")) light.color = color(spec["color"], where + " color");
    if (spec.contains("intensity")) {
      light.intensity = number(spec["intensity"], where + " intensity");
      if (light.intensity < 0.0f) fail(where + " intensity must not be negative");
    }
    return light;
  }

  const JsonReader& reader_;
  GraphKind kind_;
};

}  // namespace

SceneDesc parse_scene(const JsonReader& reader, const json& scene, GraphKind kind) {
  return SceneParser(reader, kind).parse(scene);
}

}  // namespace shadetree
