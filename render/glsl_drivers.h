// Each graph kind's driver written in GLSL: the kinds table's glsl_driver
// (render/graph_kinds.h), which render/glsl_shader.cpp puts around the
// graph's function. A driver gives the functions it needs and the
// statements of one pixel, which read
//   vec2 st_coordinate  the pixel's centre, from the bottom-left (gl_FragCoord.xy)
//   vec2 st_size        the image, in pixels
//   float st_frame      the animation frame (a uniform, or Shadertoy's iTime * 24)
// and set vec3 st_color and float st_alpha (1 unless the graph has one).
#pragma once

#include <string>

#include "glslgen/emit_glsl.h"
#include "graph/graph.h"

namespace shadetree {

struct GlslDriver {
  std::string functions;  // before main
  std::string pixel;      // statements of main
};

// The value of the global `time` in a driver's functions.
std::string glsl_time();

// As render/texture_driver.cpp places its pixels in the graph's domain.
Result<GlslDriver> texture_glsl(const Graph& graph, const GlslFunction& function);
// As render/environment_driver.cpp draws its latitude-longitude panorama.
Result<GlslDriver> environment_glsl(const Graph& graph, const GlslFunction& function);
// render/volume_driver.cpp's march with exact shadows (`--shadows exact`),
// the gradient by two probes, refraction where the index changes.
Result<GlslDriver> volume_glsl(const Graph& graph, const GlslFunction& function);
// render/surface_driver.cpp at one sample per pixel, on its scene's
// analytic objects.
Result<GlslDriver> surface_glsl(const Graph& graph, const GlslFunction& function);

}  // namespace shadetree
