// The hypertexture ray march as GLSL (render/glsl_drivers.h): Perlin &
// Hoffert 1989 section 3.1 in a fragment shader, as Gilet & Dischler 2010
// section 6 ran theirs, one ray per pixel. It translates
// render/volume_driver.cpp's Marcher with exact shadows and no empty-space
// skipping (`shadetree render --shadows exact`): the same segments,
// jitter, compositing per reference step, probed gradients, shadow rays
// and termination, so that the two agree up to the GPU's rounding.
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "graph/parse_volume.h"
#include "nodes/lane_trace.h"
#include "render/glsl_drivers.h"
#include "render/scene_glsl.h"
#include "render/volume_driver.h"

namespace shadetree {
namespace {

using lanes::glsl_float;

// The march, after the scene's functions and the constants of the volume.
constexpr const char* march_functions = R"(
// RayFrame (render/density_gradient.h): the direction and two unit vectors
// perpendicular to it and to each other.
void st_ray_frame(vec3 along, out vec3 across_v, out vec3 across_w) {
  vec3 helper = abs(along.x) < 0.6 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  across_v = normalize(cross(along, helper));
  across_w = cross(along, across_v);
}

// Wellons' lowbias32 of pixel (column, row) and an index (render/pixel_hash.h).
float st_pixel_random(int column, int row, int index) {
  uint x = uint(column) * 73856093u ^ uint(row) * 19349663u ^ uint(index) * 83492791u;
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return float(x >> 8) * (1.0 / 16777216.0);
}

// 1989: alpha_k = 1 - (1 - opacity)^(length / reference step).
float st_segment_alpha(float opacity, float segment) {
  return opacity >= 1.0 ? 1.0 : 1.0 - pow(1.0 - opacity, segment / st_reference_step);
}

// What reaches x of light `light` through the volume: a march at the
// shadow step, multiplying by 1 - alpha of every segment, until the ray
// leaves the box, reaches the light or lets less than the termination through.
float st_shadow(vec3 x, int light) {
  float distance;
  vec3 direction = st_direction_to_light(light, x, distance);
  float near, far;
  int near_axis, far_axis;
  float t = 0.0, end = 0.0;
  if (st_clip_to_box(x, direction, st_bounds_min, st_bounds_max, near, far, near_axis, far_axis)) {
    t = max(near, 0.0);
    end = min(far, distance);
  }
  float transmittance = 1.0;
  int segments_left = int(min(ceil((end - t) / st_shadow_step), st_max_steps_across)) + 1;
  while (t < end && segments_left > 0) {
    float opacity = st_sample(x + (t + 0.5 * min(st_shadow_step, end - t)) * direction, direction).opacity;
    transmittance *= 1.0 - st_segment_alpha(opacity, min(st_shadow_step, end - t));
    t += st_shadow_step;
    --segments_left;
    if (transmittance < st_termination) return 0.0;
  }
  return transmittance;
}

// Lit by the scene's lights, each through the volume where `shadowed`,
// from `offset` out along the normal.
vec3 st_lit(vec3 color, vec3 point, vec3 normal, vec3 to_viewer, bool shadowed, float offset) {
  float transmittance[st_light_slots];
  for (int l = 0; l < st_light_slots; ++l)
    transmittance[l] = shadowed && l < st_lights ? st_shadow(point + offset * normal, l) : 1.0;
  return st_light_point(color, 0.25, 0.35, vec3(0.0), point, normal, normal, to_viewer, st_shadows, transmittance);
}

// An opaque object of the scene, seen from `to_viewer`, two-sided.
vec3 st_object_color_at(st_Hit hit, vec3 to_viewer) {
  vec3 color = st_object_color[hit.object];
  if (!st_lighting) return color;
  vec3 normal = dot(hit.world_normal, to_viewer) < 0.0 ? -hit.world_normal : hit.world_normal;
  return st_lit(color, hit.world_point, normal, to_viewer, st_shadows, 1e-4 * (1.0 + length(hit.world_point)));
}

// What the ray from `origin` along unit `along` through pixel (column,
// row) sees: the volume composited front to back over what lies behind it.
vec3 st_march(vec3 origin, vec3 along, int column, int row) {
  st_Hit hit;
  bool has_hit = st_intersect(origin, along, 0.0, st_infinity, hit);
  float near, far;
  int near_axis, far_axis;
  bool in_box = st_clip_to_box(origin, along, st_bounds_min, st_bounds_max, near, far, near_axis, far_axis);
  if (!in_box || far <= 0.0 || (has_hit && hit.t <= near))
    return has_hit ? st_object_color_at(hit, -along) : st_background;
  vec3 across_v, across_w;
  st_ray_frame(along, across_v, across_w);
  float entry = max(near, 0.0);
  float exit = has_hit ? min(far, hit.t) : far;
  float jitter = st_jitter ? st_pixel_random(column, row, 0) : 0.5;
  // -1: the probe before the entry, for the first gradient.
  int segment = st_probes ? -1 : 0;
  float previous_t = 0.0, previous_density = 0.0;
  float ior = 1.0;  // of what the ray travels through
  vec3 color = vec3(0.0);
  float alpha = 0.0;
  for (int taken = 0; taken < st_max_samples; ++taken) {
    float start = entry + float(segment) * st_step;
    float segment_length = min(st_step, exit - start);
    float t = segment < 0 ? entry - (1.0 - jitter) * st_step : start + jitter * segment_length;
    vec3 x = origin + t * along;
    st_Sample here = st_sample(x, along);
    vec3 normal = -along;
    if (st_gradients && segment >= 0 && here.density > 0.0 && here.density < 1.0) {
      vec3 gradient = -here.normal;
      if (st_probes)
        gradient = (here.density - previous_density) / max(t - previous_t, 1e-30) * along +
                   (st_sample(x + st_step * across_v, along).density - here.density) / st_step * across_v +
                   (st_sample(x + st_step * across_w, along).density - here.density) / st_step * across_w;
      float size = length(gradient);
      if (size > 0.0 && !isinf(size) && !isnan(size)) normal = -gradient / size;
    }
    if (segment >= 0 && here.opacity > 0.0) {
      vec3 shaded = here.color;
      // Faint samples (per reference step, through what the ray still lets
      // through) send no shadow rays.
      if (st_lighting)
        shaded = st_lit(shaded, x, normal, -along, st_shadows && here.opacity * (1.0 - alpha) >= 1.0 / 64.0,
                        2.0 * st_reference_step);
      float weight = st_segment_alpha(here.opacity, segment_length) * (1.0 - alpha);
      float sum = shaded.x + shaded.y + shaded.z;
      if (!isinf(sum) && !isnan(sum)) {
        color += weight * shaded;
        alpha += weight;
      }
    }
    previous_t = t;
    previous_density = here.density;
    ++segment;
    // 1989 blue glass: where the index changes, the ray bends by Snell's
    // law about the gradient (or reflects past the critical angle) and
    // marches on from the sample through the rest of the box.
    float sample_ior = clamp(here.ior, 0.1, 10.0);
    if (st_refracts && segment > 0 && abs(sample_ior - ior) > 1e-4) {
      vec3 n = normal;
      float cosine = -dot(n, along);
      if (cosine < 0.0) {
        n = -n;
        cosine = -cosine;
      }
      float eta = ior / sample_ior;
      float k = 1.0 - eta * eta * (1.0 - cosine * cosine);
      vec3 bent = k < 0.0 ? along + 2.0 * cosine * n : eta * along + (eta * cosine - sqrt(k)) * n;
      float bent_length = length(bent);
      ior = sample_ior;
      if (bent_length > 0.0 && !isinf(bent_length) &&
          st_clip_to_box(x, bent / bent_length, st_bounds_min, st_bounds_max, near, far, near_axis, far_axis)) {
        origin = x;
        along = bent / bent_length;
        st_ray_frame(along, across_v, across_w);
        entry = 0.0;
        has_hit = st_intersect(origin, along, 0.0, st_infinity, hit);
        exit = max(has_hit ? min(far, hit.t) : far, 0.0);
        segment = -1;
      }
    }
    if (entry + float(segment) * st_step >= exit || alpha >= 1.0 - st_termination) break;
  }
  if (has_hit && alpha < 1.0 - st_termination) return color + (1.0 - alpha) * st_object_color_at(hit, -along);
  return color + (1.0 - alpha) * st_background;
}
)";

// The sampler the march calls: the graph at P seen along I, as the
// marcher's kernel calls give it (filter_width the step, no incoming
// density, N and uv 0): its density, its opacity (default: the density)
// clamped, its colour (default: white), normal and index of refraction.
std::string sampler(const GlslFunction& function) {
  std::ostringstream out;
  out << "\nstruct st_Sample {\n  float density, opacity;\n  vec3 color, normal;\n  float ior;\n};\n\n"
      << "st_Sample st_sample(vec3 P, vec3 I) {\n"
      << function.output_declarations("  ") << "  "
      << function.call([](GlobalId id) -> std::string {
           switch (id) {
             case GlobalId::P: return "P";
             case GlobalId::I: return "I";
             case GlobalId::filter_width:
             case GlobalId::step_size: return "st_step";
             case GlobalId::time: return glsl_time();
             case GlobalId::frame: return "st_frame";
             default: {
               const GlobalDef& global = global_def(id);
               return global.components == 1 ? "0.0" : glsl_vector_type(global.components) + "(0.0)";
             }
           }
         })
      << "\n  return st_Sample(out_density, clamp("
      << (function.writes(OutputId::opacity) ? "out_opacity" : "out_density") << ", 0.0, 1.0), "
      << (function.writes(OutputId::color) ? "out_color" : "vec3(1.0)") << ", "
      << (function.writes(OutputId::normal) ? "out_normal" : "vec3(0.0)") << ", "
      << (function.writes(OutputId::ior) ? "out_ior" : "1.0") << ");\n}\n";
  return out.str();
}

}  // namespace

Result<GlslDriver> volume_glsl(const Graph& graph, const GlslFunction& function) {
  if (!graph.render.volume) return invalid_input("a volume graph needs render.volume to be marched");
  const VolumeDesc& volume = *graph.render.volume;
  const SceneDesc scene = volume_scene(graph.render.scene);
  Result<std::string> scene_text = scene_glsl(scene);
  if (!scene_text) return scene_text.error();
  const bool lit = scene.lighting == Lighting::lit;
  const bool refracts = function.writes(OutputId::ior);
  const bool gradients = lit || refracts;
  // However its rays bend, a pixel's march takes at most this many
  // samples: eight times the steps across the box's diagonal (a GPU must
  // not loop for ever; the CPU's rays end where their bends let them).
  const glm::vec3 diagonal(volume.bounds_max[0] - volume.bounds_min[0], volume.bounds_max[1] - volume.bounds_min[1],
                           volume.bounds_max[2] - volume.bounds_min[2]);
  const float samples = 8.0f * (std::ceil(glm::length(diagonal) / march_step(volume)) + 2.0f);
  std::ostringstream out;
  out << *scene_text << "\n// The volume (render.volume) and the march.\n"
      << "const vec3 st_bounds_min = " << glsl_vec3(volume.bounds_min) << ";\n"
      << "const vec3 st_bounds_max = " << glsl_vec3(volume.bounds_max) << ";\n"
      << "const float st_step = " << glsl_float(march_step(volume)) << ";\n"
      << "const float st_reference_step = " << glsl_float(reference_step(volume)) << ";\n"
      << "const float st_shadow_step = " << glsl_float(reference_step(volume)) << ";\n"
      << "const float st_max_steps_across = " << glsl_float(max_steps_across) << ";\n"
      << "const float st_termination = " << glsl_float(default_termination) << ";\n"
      << "const bool st_jitter = " << (volume.jitter ? "true" : "false") << ";\n"
      << "const bool st_lighting = " << (lit ? "true" : "false") << ";\n"
      << "const bool st_shadows = " << (lit && scene.shadows && !scene.lights.empty() ? "true" : "false") << ";\n"
      << "const bool st_gradients = " << (gradients ? "true" : "false") << ";\n"
      << "const bool st_probes = " << (gradients && !function.writes(OutputId::normal) ? "true" : "false") << ";\n"
      << "const bool st_refracts = " << (refracts ? "true" : "false") << ";\n"
      << "const int st_max_samples = " << static_cast<long>(samples) << ";\n"
      << sampler(function) << march_functions;
  const std::string pixel =
      "  vec2 st_pixel = vec2(st_coordinate.x, st_size.y - st_coordinate.y);\n"
      "  vec3 st_origin, st_direction;\n"
      "  st_camera_ray(st_pixel, st_size, st_origin, st_direction);\n"
      "  st_color = st_march(st_origin, st_direction, int(st_pixel.x), int(st_pixel.y));\n";
  return GlslDriver{out.str(), pixel};
}

}  // namespace shadetree
