#include "render/glsl_shader.h"

#include <sstream>

#include "graph/generated_names.h"
#include "nodes/globals.h"
#include "nodes/lane_trace.h"
#include "render/glsl_drivers.h"
#include "render/graph_kinds.h"

namespace shadetree {
namespace {

std::string header(const Graph& graph, const std::string& function, bool shadertoy) {
  std::ostringstream out;
  if (!shadertoy) out << "#version 300 es\n";
  out << "// " << function << ": the " << graph_kind_name(graph.kind) << " graph "
      << (graph.file.empty() ? std::string("given") : quoted_text(graph.file)) << ", written by `shadetree emit --glsl"
      << (shadertoy ? " --shadertoy" : "") << "`.\n";
  if (shadertoy) {
    out << "// Paste it into Shadertoy's Image tab. time is iTime; the frame is iTime * 24.\n";
    return out.str();
  }
  out << "// GLSL ES 3.00 (WebGL 2); desktop GL 3.3 and later take it with \"#version 330 core\" as the\n"
      << "// first line. It computes what shadetree's interpreter computes, in the same operations;\n"
      << "// GPUs may round division, sqrt and fused multiply-adds differently (docs/glsl.md).\n"
      << "// Draw a full-screen triangle with st_resolution = the target's size in pixels and\n"
      << "// st_frame = the animation frame; st_fragment gets colour and alpha.\n"
      << "precision highp float;\nprecision highp int;\n";
  return out.str();
}

// What the driver reads besides the params: the image's size and the frame.
std::string driver_inputs(bool shadertoy) {
  if (shadertoy) return "\nfloat st_frame;  // iTime * 24, set by mainImage\n";
  return "\nuniform vec2 st_resolution;  // the image, in pixels\n"
         "uniform float st_frame;      // the animation frame\n"
         "out vec4 st_fragment;\n";
}

// main() (or Shadertoy's mainImage) around the driver's statements of a
// pixel, which read st_coordinate, st_size and st_frame and set st_color
// and st_alpha.
std::string main_function(const std::string& pixel, bool shadertoy) {
  std::ostringstream out;
  const std::string results = "  vec3 st_color = vec3(0.0);\n  float st_alpha = 1.0;\n";
  if (shadertoy) {
    out << "\nvoid mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        << "  st_frame = iTime * " << lanes::glsl_float(frames_per_second) << ";\n"
        << "  vec2 st_coordinate = fragCoord;\n  vec2 st_size = iResolution.xy;\n"
        << results << pixel << "  fragColor = vec4(st_color, 1.0);\n}\n";
    return out.str();
  }
  out << "\nvoid main() {\n  vec2 st_coordinate = gl_FragCoord.xy;\n  vec2 st_size = st_resolution;\n"
      << results << pixel << "  st_fragment = vec4(st_color, st_alpha);\n}\n";
  return out.str();
}

}  // namespace

Result<GlslShader> glsl_shader(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                               const GlslOptions& options) {
  Result<GlslFunction> function = emit_glsl_function(graph, ir, param_block, options);
  if (!function) return function.error();
  Result<GlslDriver> driver = graph_kind_driver(graph.kind).glsl_driver(graph, *function);
  if (!driver) {
    Diagnostic named = driver.error();
    if (named.file.empty()) named.file = graph.file;
    return named;
  }
  return GlslShader{header(graph, function->name, options.shadertoy) + driver_inputs(options.shadertoy) +
                        function->declarations + driver->functions +
                        main_function(driver->pixel, options.shadertoy),
                    function->uniforms};
}

}  // namespace shadetree
