// The surface driver as GLSL (render/glsl_drivers.h): Perlin 1985's
// shading of visible points, one ray per pixel through its centre (as
// `shadetree render` at one sample per pixel), cast at the scene's
// analytic objects. It translates render/surface_driver.cpp: the globals
// of the visible point in its object's space, the pixel's footprint by ray
// differentials, then the lighting of what the graph returns.
#include <sstream>

#include "render/glsl_drivers.h"
#include "render/scene_glsl.h"
#include "scene/preview_scene.h"

namespace shadetree {
namespace {

// Igehy 1999: where the rays through the neighbouring pixels meet the
// tangent plane at the hit, in the units of object-space P.
constexpr const char* footprint_function = R"(
float st_footprint(st_Hit hit, vec2 pixel, vec2 size) {
  const float widest = 1e6;  // at grazing angles the footprint is unbounded
  float width = 0.0;
  for (int k = 0; k < 2; ++k) {
    vec3 origin, direction;
    st_camera_ray(pixel + (k == 0 ? vec2(1.0, 0.0) : vec2(0.0, 1.0)), size, origin, direction);
    float facing = dot(direction, hit.world_normal);
    if (abs(facing) < 1e-12) return widest;
    float t = dot(hit.world_point - origin, hit.world_normal) / facing;
    vec3 offset = mat3(st_world_to_object[hit.object]) * (origin + t * direction - hit.world_point);
    width = max(width, length(offset));
  }
  return isinf(width) || isnan(width) ? widest : min(width, widest);
}
)";

// The argument of the graph's function for global `id` at the visible
// point: st_ and its name, time from the frame.
std::string argument(GlobalId id) {
  switch (id) {
    case GlobalId::time: return glsl_time();
    case GlobalId::frame: return "st_frame";
    default: return "st_" + std::string(global_def(id).name);
  }
}

std::string shading(const GlslFunction& function) {
  std::ostringstream out;
  out << "\n// What the camera sees at pixel (from the top-left corner) of an image of `size`.\n"
      << "vec3 st_shade(vec2 pixel, vec2 size) {\n"
      << "  vec3 origin, direction;\n"
      << "  st_camera_ray(pixel, size, origin, direction);\n"
      << "  st_Hit hit;\n"
      << "  if (!st_intersect(origin, direction, 0.0, st_infinity, hit)) return st_background;\n"
      << "  // Two-sided: the graph and the lights see the side facing the viewer.\n"
      << "  bool back_face = dot(hit.world_normal, direction) > 0.0;\n"
      << "  vec3 geometric_normal = back_face ? -hit.world_normal : hit.world_normal;\n"
      << "  mat3 to_object = mat3(st_world_to_object[hit.object]);\n"
      << "  vec3 st_P = hit.object_point;\n"
      << "  vec3 st_N = back_face ? -hit.object_normal : hit.object_normal;\n"
      << "  vec3 st_I = normalize(to_object * direction);\n"
      << "  float light_distance;\n"
      << "  vec3 st_L = normalize(to_object * (st_lights > 0 ? st_direction_to_light(0, hit.world_point, "
         "light_distance) : vec3(0.0, 1.0, 0.0)));\n"
      << "  vec2 st_uv = hit.uv;\n"
      << "  float st_surface = float(st_object_id[hit.object]);\n"
      << "  float st_filter_width = st_footprint(hit, pixel, size);\n"
      << "  vec3 st_light_color = st_lights > 0 ? st_light_radiance[0] : vec3(0.0);\n"
      << function.output_declarations("  ") << "  " << function.call(argument) << "\n"
      << "  vec3 result = out_color;\n"
      << "  if (st_lighting) {\n"
      << "    vec3 shading_normal = geometric_normal;\n";
  if (function.writes(OutputId::normal))
    out << "    // The graph's normal is in object space, like the N it read.\n"
        << "    vec3 normal = st_normal_to_world[hit.object] * out_normal;\n"
        << "    float normal_length = length(normal);\n"
        << "    if (normal_length > 0.0 && !isinf(normal_length) && !isnan(normal_length))\n"
        << "      shading_normal = normal / normal_length;\n";
  out << "    float transmittance[st_light_slots];\n"
      << "    for (int l = 0; l < st_light_slots; ++l) transmittance[l] = 1.0;\n"
      << "    result = st_light_point(out_color, " << (function.writes(OutputId::specular) ? "out_specular" : "0.25")
      << ", " << (function.writes(OutputId::roughness) ? "out_roughness" : "0.35") << ", "
      << (function.writes(OutputId::emission) ? "out_emission" : "vec3(0.0)")
      << ", hit.world_point, shading_normal, geometric_normal, -direction, st_shadows, transmittance);\n"
      << "  }\n";
  if (function.writes(OutputId::opacity))
    out << "  float opacity = clamp(out_opacity, 0.0, 1.0);\n"
        << "  result = opacity * result + (1.0 - opacity) * st_background;\n";
  out << "  return result;\n}\n";
  return out.str();
}

}  // namespace

Result<GlslDriver> surface_glsl(const Graph& graph, const GlslFunction& function) {
  Result<SceneDesc> scene = surface_scene_desc(graph);
  if (!scene) return scene.error();
  Result<std::string> scene_text = scene_glsl(*scene);
  if (!scene_text) return scene_text.error();
  std::ostringstream out;
  out << *scene_text << "\nconst bool st_lighting = " << (scene->lighting == Lighting::lit ? "true" : "false")
      << ";\nconst bool st_shadows = " << (scene->shadows ? "true" : "false") << ";\n"
      << footprint_function << shading(function);
  return GlslDriver{out.str(),
                    "  st_color = st_shade(vec2(st_coordinate.x, st_size.y - st_coordinate.y), st_size);\n"};
}

}  // namespace shadetree
