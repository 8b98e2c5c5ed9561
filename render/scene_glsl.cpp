#include "render/scene_glsl.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "nodes/lane_trace.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace shadetree {
namespace {

using lanes::glsl_float;
using lanes::glsl_int;

// The shape codes of st_object_shape.
constexpr int shape_sphere = 0, shape_torus = 1, shape_plane = 2, shape_box = 3;

std::string vec3_text(float x, float y, float z) { return glsl_vec3({x, y, z}); }
std::string vec3_text(const std::array<float, 3>& v) { return glsl_vec3(v); }
std::string vec3_text(const glm::vec3& v) { return glsl_vec3({v.x, v.y, v.z}); }

template <class Matrix>
std::string matrix_text(const char* type, const Matrix& matrix, int size) {
  std::string text = std::string(type) + "(";
  for (int column = 0; column < size; ++column)
    for (int row = 0; row < size; ++row)
      text += (column + row > 0 ? ", " : "") + glsl_float(matrix[column][row]);
  return text + ")";
}

// "const TYPE NAME[N] = TYPE[N](a, b, ...);" of at least one entry
// (`none` where there is no object or light: GLSL has no empty arrays).
std::string const_array(const std::string& type, const std::string& name, const std::vector<std::string>& entries,
                        const std::string& none) {
  const std::vector<std::string> values = entries.empty() ? std::vector<std::string>{none} : entries;
  std::string text = "const " + type + " " + name + "[" + std::to_string(values.size()) + "] = " + type + "[" +
                     std::to_string(values.size()) + "](";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i > 0 ? ",\n    " : "") + values[i];
  return text + ");\n";
}

const char* object_type_name(ObjectType type) {
  return type == ObjectType::mesh ? "a mesh" : "a surface of revolution";
}

// Camera::ray, Scene::intersect and occluded, the shapes' closed forms
// (scene/shapes.cpp, in float where they use double), direction_to_light
// and light_point (scene/lighting.cpp).
constexpr const char* scene_functions = R"(
const float st_infinity = 3.40282347e38;  // the largest float: GLSL ES has no constant infinity
const float st_two_pi = 6.28318530717958647;

void st_camera_ray(vec2 pixel, vec2 size, out vec3 origin, out vec3 direction) {
  vec3 forward = normalize(st_camera_target - st_camera_position);
  vec3 right = normalize(cross(forward, st_camera_up));
  vec3 up = cross(right, forward);
  float half_width = st_camera_half_height * size.x / size.y;
  float sx = (2.0 * pixel.x / size.x - 1.0) * half_width;
  float sy = (1.0 - 2.0 * pixel.y / size.y) * st_camera_half_height;
  if (st_camera_orthographic) {
    origin = st_camera_position + sx * right + sy * up;
    direction = forward;
  } else {
    origin = st_camera_position;
    direction = normalize(forward + sx * right + sy * up);
  }
}

// Kay and Kajiya's slabs: where the ray is inside [lo, hi], entering
// through a face normal to near_axis and leaving through one normal to far_axis.
bool st_clip_to_box(vec3 origin, vec3 direction, vec3 lo, vec3 hi, out float near, out float far,
                    out int near_axis, out int far_axis) {
  near = -st_infinity;
  far = st_infinity;
  near_axis = 0;
  far_axis = 0;
  for (int axis = 0; axis < 3; ++axis) {
    float o = origin[axis], d = direction[axis];
    if (d == 0.0) {
      if (o < lo[axis] || o > hi[axis]) return false;
      continue;
    }
    float t0 = (lo[axis] - o) / d, t1 = (hi[axis] - o) / d;
    if (t0 > t1) { float swapped = t0; t0 = t1; t1 = swapped; }
    if (t0 > near) { near = t0; near_axis = axis; }
    if (t1 < far) { far = t1; far_axis = axis; }
  }
  return near <= far;
}

float st_longitude(vec3 p) {
  float u = atan(-p.z, p.x) / st_two_pi;
  return u < 0.0 ? u + 1.0 : u;
}

// The smaller root of a t^2 + 2 b t + c = 0 in [t_min, t_max], else the larger.
bool st_nearest_root(float a, float b, float c, float t_min, float t_max, out float t) {
  t = 0.0;
  if (a == 0.0) {
    if (b == 0.0) return false;
    t = -c / (2.0 * b);
    return t >= t_min && t <= t_max;
  }
  float discriminant = b * b - a * c;
  if (discriminant < 0.0) return false;
  float q = -(b + (b < 0.0 ? -1.0 : 1.0) * sqrt(discriminant));
  float t0 = q / a, t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) { float swapped = t0; t0 = t1; t1 = swapped; }
  t = t0 >= t_min && t0 <= t_max ? t0 : t1;
  return t >= t_min && t <= t_max;
}

float st_torus_distance(vec2 radii, vec3 p) {
  float ring = sqrt(p.x * p.x + p.z * p.z) - radii.x;
  return sqrt(ring * ring + p.y * p.y) - radii.y;
}

// Hit t, object-space normal and uv of shape `shape` of size `size`
// (sphere: radius in x; torus: major and minor radius; box: half size).
bool st_intersect_shape(int shape, vec3 size, vec3 o, vec3 d, float t_min, float t_max, out float t,
                        out vec3 normal, out vec2 uv) {
  t = 0.0;
  normal = vec3(0.0, 1.0, 0.0);
  uv = vec2(0.0);
  if (shape == ST_SPHERE) {
    if (!st_nearest_root(dot(d, d), dot(o, d), dot(o, o) - size.x * size.x, t_min, t_max, t)) return false;
    vec3 p = o + t * d;
    normal = normalize(p);
    uv = vec2(st_longitude(p), asin(clamp(normal.y, -1.0, 1.0)) / (st_two_pi / 2.0) + 0.5);
    return true;
  }
  if (shape == ST_TORUS) {
    // Sphere tracing (Hart 1996) inside the bounding sphere.
    float speed = length(d);
    if (!(speed > 0.0)) return false;
    vec3 direction = d / speed;
    float bound = size.x + size.y;
    float b = dot(o, direction), c = dot(o, o) - bound * bound;
    float discriminant = b * b - c;
    if (discriminant <= 0.0) return false;
    float root = sqrt(discriminant);
    float s = max(t_min * speed, -b - root);
    float s_end = min(t_max * speed, -b + root);
    if (s > s_end) return false;
    float epsilon = 1e-6 * bound;
    float side = st_torus_distance(size.xy, o + s * direction) < 0.0 ? -1.0 : 1.0;
    for (int step = 0; step < 1024 && s <= s_end; ++step) {
      float distance = side * st_torus_distance(size.xy, o + s * direction);
      if (distance < epsilon) {
        t = s / speed;
        if (t < t_min || t > t_max) return false;
        vec3 p = o + s * direction;
        float ring_length = sqrt(p.x * p.x + p.z * p.z);
        vec3 centre = ring_length > 0.0 ? vec3(p.x, 0.0, p.z) * (size.x / ring_length) : vec3(size.x, 0.0, 0.0);
        normal = normalize(p - centre);
        float radial = dot(p - centre, normalize(centre));
        float v = atan(p.y, radial) / st_two_pi;
        uv = vec2(st_longitude(p), v < 0.0 ? v + 1.0 : v);
        return true;
      }
      s += max(distance, epsilon);
    }
    return false;
  }
  if (shape == ST_PLANE) {
    if (d.y == 0.0) return false;
    t = -o.y / d.y;
    if (!(t >= t_min && t <= t_max)) return false;
    vec3 p = o + t * d;
    uv = vec2(p.x, p.z);
    return true;
  }
  float near, far;
  int near_axis, far_axis;
  if (!st_clip_to_box(o, d, -size, size, near, far, near_axis, far_axis)) return false;
  t = near;
  int axis = near_axis;
  if (t < t_min) { t = far; axis = far_axis; }
  if (t < t_min || t > t_max) return false;
  vec3 p = o + t * d;
  normal = vec3(0.0);
  normal[axis] = p[axis] > 0.0 ? 1.0 : -1.0;
  int a = axis == 0 ? 1 : 0, e = axis == 2 ? 1 : 2;
  uv = vec2((p[a] / size[a] + 1.0) / 2.0, (p[e] / size[e] + 1.0) / 2.0);
  return true;
}

struct st_Hit {
  float t;
  int object;  // index in the scene's objects
  vec3 world_point, world_normal;  // unit, out of the solid
  vec3 object_point, object_normal;
  vec2 uv;
};

// Object i on the world ray: t, and the ray (o, d), normal and uv in its space.
bool st_intersect_object(int i, vec3 origin, vec3 direction, float t_min, float t_max, out float t, out vec3 o,
                         out vec3 d, out vec3 normal, out vec2 uv) {
  o = (st_world_to_object[i] * vec4(origin, 1.0)).xyz;
  d = (st_world_to_object[i] * vec4(direction, 0.0)).xyz;
  return st_intersect_shape(st_object_shape[i], st_object_size[i], o, d, t_min, t_max, t, normal, uv);
}

bool st_intersect(vec3 origin, vec3 direction, float t_min, float t_max, out st_Hit hit) {
  bool found = false;
  hit = st_Hit(0.0, 0, vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec2(0.0));
  for (int i = 0; i < st_objects; ++i) {
    float t;
    vec3 o, d, normal;
    vec2 uv;
    if (!st_intersect_object(i, origin, direction, t_min, t_max, t, o, d, normal, uv)) continue;
    t_max = t;
    found = true;
    hit.t = t;
    hit.object = i;
    hit.object_point = o + t * d;
    hit.object_normal = normal;
    hit.world_point = origin + t * direction;
    hit.world_normal = normalize(st_normal_to_world[i] * normal);
    hit.uv = uv;
  }
  return found;
}

bool st_occluded(vec3 origin, vec3 direction, float t_min, float t_max) {
  for (int i = 0; i < st_objects; ++i) {
    float t;
    vec3 o, d, normal;
    vec2 uv;
    if (st_intersect_object(i, origin, direction, t_min, t_max, t, o, d, normal, uv)) return true;
  }
  return false;
}

vec3 st_direction_to_light(int light, vec3 point, out float distance) {
  if (st_light_point_type[light] == 0) {
    distance = st_infinity;
    return -st_light_direction[light];
  }
  vec3 offset = st_light_position[light] - point;
  distance = length(offset);
  return distance > 0.0 ? offset / distance : vec3(0.0, 1.0, 0.0);
}

// Lambert plus Blinn-Phong from each light, shadowed by the objects where
// `shadows`, times the light's transmittance through a volume.
vec3 st_light_point(vec3 color, float specular, float roughness, vec3 emission, vec3 point, vec3 n,
                    vec3 geometric_normal, vec3 to_viewer, bool shadows, float transmittance[st_light_slots]) {
  vec3 result = st_ambient * color + emission;
  float r = clamp(roughness, 0.02, 1.0);
  float exponent = 2.0 / (r * r) - 2.0;
  float offset = 1e-4 * (1.0 + length(point));
  for (int i = 0; i < st_lights; ++i) {
    float distance;
    vec3 l = st_direction_to_light(i, point, distance);
    float diffuse = dot(n, l);
    if (diffuse <= 0.0 || dot(geometric_normal, l) <= 0.0) continue;
    if (shadows && st_occluded(point + offset * geometric_normal, l, 0.0, distance)) continue;
    vec3 term = color * diffuse;
    if (specular != 0.0) {
      float facing = max(0.0, dot(n, normalize(l + to_viewer)));
      term += specular * (exponent == 0.0 ? 1.0 : pow(facing, exponent));
    }
    result += transmittance[i] * st_light_radiance[i] * term;
  }
  return result;
}
)";

}  // namespace

std::string glsl_vec3(const std::array<float, 3>& v) {
  return "vec3(" + glsl_float(v[0]) + ", " + glsl_float(v[1]) + ", " + glsl_float(v[2]) + ")";
}

Result<std::string> scene_glsl(const SceneDesc& scene) {
  if (!scene.environment.empty())
    return invalid_input("the scene's environment " + scene.environment +
                         " cannot be drawn behind a GLSL shader's scene yet; its background colour can");
  if (scene.objects.size() > max_glsl_objects)
    return invalid_input("the scene has " + std::to_string(scene.objects.size()) +
                         " objects, more than a GLSL shader tests per ray (at most " +
                         std::to_string(max_glsl_objects) + ")");
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].type == ObjectType::revolution || scene.objects[i].type == ObjectType::mesh)
      return invalid_input("scene object #" + std::to_string(i + 1) + " is " +
                           object_type_name(scene.objects[i].type) +
                           ", which a GLSL shader cannot intersect (spheres, tori, planes and boxes it can)");
  // Without meshes, building reads no file.
  Result<Scene> built = Scene::build(scene, "", {});
  if (!built) return built.error();
  std::vector<std::string> world_to_object, normal_to_world, shape, size, id, color;
  for (std::size_t i = 0; i < built->objects().size(); ++i) {
    const SceneObject& object = built->objects()[i];
    // A shader's constants must be finite (GLSL ES has no constant infinity).
    bool finite = true;
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 4; ++row) finite = finite && std::isfinite(object.world_to_object[column][row]);
    for (int column = 0; column < 3; ++column)
      for (int row = 0; row < 3; ++row) finite = finite && std::isfinite(object.normal_to_world[column][row]);
    if (!finite)
      return invalid_input("scene object #" + std::to_string(i + 1) +
                           "'s transform has no finite inverse in single precision, which a GLSL shader needs");
    world_to_object.push_back(matrix_text("mat4", object.world_to_object, 4));
    normal_to_world.push_back(matrix_text("mat3", object.normal_to_world, 3));
    id.push_back(glsl_int(object.id));
    color.push_back(vec3_text(object.color));
    if (const Sphere* sphere = std::get_if<Sphere>(&object.shape)) {
      shape.push_back(glsl_int(shape_sphere));
      size.push_back(vec3_text(sphere->radius, 0.0f, 0.0f));
    } else if (const Torus* torus = std::get_if<Torus>(&object.shape)) {
      shape.push_back(glsl_int(shape_torus));
      size.push_back(vec3_text(torus->major_radius, torus->minor_radius, 0.0f));
    } else if (const Box* box = std::get_if<Box>(&object.shape)) {
      shape.push_back(glsl_int(shape_box));
      size.push_back(vec3_text(box->half_size));
    } else {
      shape.push_back(glsl_int(shape_plane));
      size.push_back(vec3_text(0.0f, 0.0f, 0.0f));
    }
  }
  std::vector<std::string> light_type, direction, position, radiance;
  for (const Light& light : built->lights()) {
    light_type.push_back(light.type == LightType::point ? "1" : "0");
    direction.push_back(vec3_text(light.direction));
    position.push_back(vec3_text(light.position));
    radiance.push_back(vec3_text(light.radiance));
  }
  const CameraDesc& camera = scene.camera;
  std::ostringstream out;
  out << "\n// The scene: its camera, objects and lights (shadetree's scene/).\n"
      << "const vec3 st_camera_position = " << vec3_text(camera.position) << ";\n"
      << "const vec3 st_camera_target = " << vec3_text(camera.target) << ";\n"
      << "const vec3 st_camera_up = " << vec3_text(camera.up) << ";\n"
      << "const float st_camera_half_height = " << glsl_float(camera_half_height(camera)) << ";\n"
      << "const bool st_camera_orthographic = " << (camera.orthographic ? "true" : "false") << ";\n"
      << "const vec3 st_background = " << vec3_text(scene.background) << ";\n"
      << "const vec3 st_ambient = " << vec3_text(scene.ambient) << ";\n"
      << "const int ST_SPHERE = " << shape_sphere << ", ST_TORUS = " << shape_torus << ", ST_PLANE = " << shape_plane
      << ", ST_BOX = " << shape_box << ";\n"
      << "const int st_objects = " << scene.objects.size() << ";\n"
      << const_array("mat4", "st_world_to_object", world_to_object, "mat4(1.0)")
      << const_array("mat3", "st_normal_to_world", normal_to_world, "mat3(1.0)")
      << const_array("int", "st_object_shape", shape, "0") << const_array("vec3", "st_object_size", size, "vec3(0.0)")
      << const_array("int", "st_object_id", id, "0") << const_array("vec3", "st_object_color", color, "vec3(0.0)")
      << "const int st_lights = " << scene.lights.size() << ";\n"
      << "const int st_light_slots = " << std::max<std::size_t>(scene.lights.size(), 1) << ";\n"
      << const_array("int", "st_light_point_type", light_type, "0")
      << const_array("vec3", "st_light_direction", direction, "vec3(0.0, -1.0, 0.0)")
      << const_array("vec3", "st_light_position", position, "vec3(0.0)")
      << const_array("vec3", "st_light_radiance", radiance, "vec3(0.0)") << scene_functions;
  return out.str();
}

}  // namespace shadetree
