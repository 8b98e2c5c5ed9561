// The texture and environment drivers as GLSL (render/glsl_drivers.h).
#include <sstream>

#include "nodes/lane_trace.h"
#include "render/glsl_drivers.h"

namespace shadetree {
namespace {

using lanes::glsl_float;

// The call of the graph's function with the globals named st_ and their
// name, time from the frame, and the outputs to st_color and st_alpha.
std::string call_and_results(const GlslFunction& function) {
  return function.output_declarations("  ") + "  " + function.call([](GlobalId id) {
           if (id == GlobalId::time) return glsl_time();
           if (id == GlobalId::frame) return std::string("st_frame");
           return "st_" + std::string(global_def(id).name);
         }) + "\n  st_color = out_color;\n" +
         (function.writes(OutputId::alpha) ? "  st_alpha = out_alpha;\n" : "");
}

}  // namespace

std::string glsl_time() { return "st_frame / " + glsl_float(frames_per_second); }

// u, v from the pixel centre (rows counted from the top), P through the
// graph's domain, N facing the viewer, filter_width a pixel's size.
Result<GlslDriver> texture_glsl(const Graph& graph, const GlslFunction& function) {
  const RenderSettings& render = graph.render;
  std::ostringstream out;
  out << "  const vec2 st_domain_min = vec2(" << glsl_float(render.domain_min[0]) << ", "
      << glsl_float(render.domain_min[1]) << ");\n"
      << "  const vec2 st_domain_max = vec2(" << glsl_float(render.domain_max[0]) << ", "
      << glsl_float(render.domain_max[1]) << ");\n"
      << "  float st_u = st_coordinate.x / st_size.x;\n"
      << "  float st_v = 1.0 - (st_size.y - st_coordinate.y) / st_size.y;\n"
      << "  vec3 st_P = vec3(st_domain_min.x + st_u * (st_domain_max.x - st_domain_min.x),\n"
      << "                   st_domain_min.y + st_v * (st_domain_max.y - st_domain_min.y), "
      << glsl_float(render.z) << ");\n"
      << "  vec3 st_N = vec3(0.0, 0.0, 1.0);\n"
      << "  vec2 st_uv = vec2(st_u, st_v);\n"
      << "  vec2 st_span = st_domain_max - st_domain_min;\n"
      << "  float st_filter_width = max(abs(st_span.x) / st_size.x, abs(st_span.y) / st_size.y);\n"
      << call_and_results(function);
  return GlslDriver{"", out.str()};
}

// Longitude 0 down -z growing toward +x, latitude +90 degrees on the top
// row; I the direction, P the same point of the unit sphere, N = -I, uv
// longitude and latitude in [0, 1], filter_width the angle of a pixel.
// GLSL's sin, cos, atan and asin stand for the C library's here.
Result<GlslDriver> environment_glsl(const Graph&, const GlslFunction& function) {
  const std::string pi = glsl_float(3.14159265358979f);
  std::ostringstream out;
  out << "  float st_longitude = 2.0 * " << pi << " * st_coordinate.x / st_size.x - " << pi << ";\n"
      << "  float st_latitude = 0.5 * " << pi << " - " << pi << " * (st_size.y - st_coordinate.y) / st_size.y;\n"
      << "  vec3 st_I = vec3(sin(st_longitude) * cos(st_latitude), sin(st_latitude), "
         "-cos(st_longitude) * cos(st_latitude));\n"
      << "  vec3 st_P = st_I;\n"
      << "  vec3 st_N = -st_I;\n"
      << "  vec2 st_uv = vec2((atan(st_I.x, -st_I.z) + " << pi << ") / (2.0 * " << pi
      << "), asin(clamp(st_I.y, -1.0, 1.0)) / " << pi << " + 0.5);\n"
      << "  float st_filter_width = " << pi << " / st_size.y;\n"
      << call_and_results(function);
  return GlslDriver{"", out.str()};
}

}  // namespace shadetree
