// A graph as a whole GLSL ES 3.00 fragment shader (`shadetree emit
// --glsl`, the editor's GPU previews): the graph's function
// (glslgen/emit_glsl.h) inside its kind's driver written in GLSL (the
// kinds table's glsl_driver: render/glsl_drivers.h), which places each
// pixel's samples as `shadetree render` does: a texture's domain, an
// environment's panorama, a volume's ray march, a surface's ray cast.
#pragma once

#include <string>
#include <vector>

#include "glslgen/emit_glsl.h"

namespace shadetree {

struct GlslShader {
  std::string source;
  std::vector<GlslUniform> uniforms;  // the params' (none with shadertoy); the driver's are st_resolution and st_frame
};

// The shader of a texture graph draws its domain, of an environment graph
// its panorama, of a volume or surface graph its scene as its camera sees
// it; with `options.shadertoy`, a mainImage for Shadertoy.
Result<GlslShader> glsl_shader(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                               const GlslOptions& options);

}  // namespace shadetree
