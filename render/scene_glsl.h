// The scene of a volume or surface graph as GLSL, for the drivers'
// shaders (render/glsl_drivers.h): its camera, its analytic objects and
// its lights, and the lighting of scene/lighting.h, each a translation of
// the C++ the drivers call, so that the shader sees what `shadetree
// render` sees.
//
// It declares
//   void st_camera_ray(vec2 pixel, vec2 size, out vec3 origin, out vec3 direction)
//       pixel from the image's top-left corner, as Camera::ray;
//   struct st_Hit { t, object, world_point, world_normal, object_point, object_normal, uv }
//   bool st_intersect(origin, direction, t_min, t_max, out st_Hit hit)  the nearest object;
//   bool st_occluded(origin, direction, t_min, t_max);
//   vec3 st_direction_to_light(int light, vec3 point, out float distance);
//   vec3 st_light_point(color, specular, roughness, emission, point, shading_normal,
//                       geometric_normal, to_viewer, bool shadows, float transmittance[st_light_slots]);
// and the constants st_lights (their count), st_light_slots (at least
// 1), st_background, st_infinity, the objects' st_world_to_object,
// st_normal_to_world, st_object_id and st_object_color.
#pragma once

#include <array>
#include <string>

#include "graph/diagnostic.h"
#include "graph/scene.h"

namespace shadetree {

// Objects a shader's scene may hold: each ray tests them all in a loop.
inline constexpr std::size_t max_glsl_objects = 64;

// "vec3(x, y, z)", each a GLSL float literal.
std::string glsl_vec3(const std::array<float, 3>& v);

// Refused in one line: a mesh or a surface of revolution (no GLSL
// intersector), an environment behind the scene, more than
// max_glsl_objects objects.
Result<std::string> scene_glsl(const SceneDesc& scene);

}  // namespace shadetree
