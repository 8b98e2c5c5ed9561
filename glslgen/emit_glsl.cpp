#include "glslgen/emit_glsl.h"

#include <algorithm>
#include <array>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "glslgen/traced_ops.h"
#include "graph/generated_names.h"
#include "ir/op_constants.h"
#include "nodes/globals.h"
#include "nodes/improved_noise_permutation.h"
#include "nodes/noise_tables.h"
#include "nodes/output_contract.h"
#include "nodes/registry.h"

namespace shadetree {
namespace {

using lanes::TraceF;
using lanes::TraceType;

// The frames of `shadetree render` (time = frame / frames_per_second).
constexpr const char* frames_per_second_literal = "24.0";

std::string glsl_vector_type(int components) {
  return components == 1 ? "float" : "vec" + std::to_string(components);
}

template <class Values, class Format>
std::string joined(const Values& values, Format format, const std::string& separator = ", ") {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += (i % 8 == 0) ? ",\n    " : separator;
    text += format(values[i]);
  }
  return text;
}

// Component c of a GLSL vector named `name` of `components` components.
std::string component(const std::string& name, int components, int c) {
  return components == 1 ? name : name + "." + "xyz"[c];
}

class GlslEmitter {
 public:
  GlslEmitter(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
              const GlslOptions& options)
      : graph_(graph), ir_(ir), param_block_(param_block), options_(options), values_(ir.code.size()) {
    // The function's name is the graph's, unless it is one the shader
    // uses itself: main, a global (its parameters), or the form of a
    // temporary (t12, s3, v7_0) or of the emitter's own names (st_, out_).
    IdentifierScope names;
    for (const char* taken : {"main", "mainImage"}) names.reserve(taken);
    for (const GlobalDef& global : globals) names.reserve(std::string(global.name));
    for (const IrParam& param : ir_.params) uniform_names_[param.name] = names.add("u_" + param.name);
    std::string function = code_identifier(options.name, "shade");
    static const std::regex internal("[tsv][0-9].*|st_.*|out_.*");
    if (std::regex_match(function, internal)) function = "graph_" + function;
    function_name_ = names.add(function);
    for (const IrInstr& instr : ir_.code)
      if (instr.kind == IrOpKind::global) reads_.insert(static_cast<GlobalId>(instr.immediate[0]));
  }

  Result<GlslShader> emit() {
    if (ir_.data.size() > max_glsl_data) return data_refusal();
    register_tables();
    lanes::TraceActivation activation(trace_);
    // A lookup in memory no array was registered for is a bug of this
    // emitter, refused in one line rather than a crash.
    try {
      if (Status traced = trace_program(); !traced) return traced.error();
    } catch (const std::logic_error& error) {
      return failure(std::string("cannot write the program as GLSL: ") + error.what());
    }
    std::ostringstream out;
    out << header() << uniforms() << tables() << function();
    if (has_main()) out << (options_.shadertoy ? shadertoy_main() : image_main());
    GlslShader shader{out.str(), {}};
    if (!options_.shadertoy)
      for (const IrParam& param : ir_.params)
        shader.uniforms.push_back({param.name, uniform_names_.at(param.name), param_type(param), param.slot,
                                   component_count(param.type)});
    return shader;
  }

 private:
  Diagnostic refusal(std::size_t instruction, const std::string& message) const {
    Diagnostic error = invalid_input(message);
    error.file = graph_.file;
    error.node = ir_.code[instruction].source;
    return error;
  }

  // The op holding the most data, named as the reason a program has too much.
  Diagnostic data_refusal() const {
    std::size_t largest = 0;
    for (std::size_t i = 1; i < ir_.code.size(); ++i)
      if (ir_.code[i].data_count > ir_.code[largest].data_count) largest = i;
    const IrInstr& instr = ir_.code[largest];
    return refusal(largest, "op \"" + op_def(instr.op).name + "\" holds " + std::to_string(instr.data_count) +
                                " floats of data, too many for a GLSL shader (at most " +
                                std::to_string(max_glsl_data) + " in all)");
  }

  // The arrays table lookups may name: the noise tables of each seed the
  // program uses, the op library's own tables, and the ops' data.
  void register_tables() {
    for (const IrInstr& instr : ir_.code)
      if (instr.kind == IrOpKind::op && op_def(instr.op).tables == OpTables::noise)
        seeds_.insert(instr.immediate[0]);
    for (int seed : seeds_) {
      const NoiseTables& tables = noise_tables(static_cast<std::uint32_t>(seed));
      const std::string suffix = "_" + std::to_string(seed);
      const std::string comment = "Perlin & Hoffert 1989 section 2.3: the noise tables of seed " + std::to_string(seed) + ".";
      add_array("st_permutation" + suffix, comment, tables.permutation);
      add_array("st_gradient_x" + suffix, comment, tables.gradient_x);
      add_array("st_gradient_y" + suffix, comment, tables.gradient_y);
      add_array("st_gradient_z" + suffix, comment, tables.gradient_z);
      add_array("st_hashed_gradient_x" + suffix, comment, tables.hashed_gradient_x);
      add_array("st_hashed_gradient_y" + suffix, comment, tables.hashed_gradient_y);
      add_array("st_hashed_gradient_z" + suffix, comment, tables.hashed_gradient_z);
    }
    add_array("st_improved_permutation", "Perlin 2002's reference permutation, twice over.", improved_noise_permutation);
    if (!ir_.data.empty()) add_array("st_data", "The ops' data: spline knots, tables, images.", ir_.data);
  }

  // A const array of `entries` (ints or floats), declared if a lookup names it.
  template <class Entries>
  void add_array(const std::string& name, const std::string& comment, const Entries& entries) {
    using Entry = std::decay_t<decltype(entries[0])>;
    const std::string type = std::is_same_v<Entry, float> ? "float" : "int";
    const std::string values = joined(entries, [](Entry v) {
      if constexpr (std::is_same_v<Entry, float>) return lanes::glsl_float(v);
      else return lanes::glsl_int(v);
    });
    arrays_.push_back({name, comment, type, std::to_string(entries.size()), values});
    trace_.add_table(entries.data(), entries.size(), name);
  }

  int components(std::int32_t value) const { return component_count(ir_.code[value].type); }

  // Component c of value `value`: a scalar read where more components are
  // declared is read splatted.
  TracedDual argument(std::int32_t value, int c) const {
    return values_[value][static_cast<std::size_t>(std::min(c, components(value) - 1))];
  }

  // The components of instruction i (op, constant, param, global,
  // component or gradient) as traced values.
  std::array<TracedDual, 3> evaluate(std::size_t i) {
    const IrInstr& instr = ir_.code[i];
    std::array<TracedDual, 3> result;
    const int count = components(static_cast<std::int32_t>(i));
    switch (instr.kind) {
      case IrOpKind::op: {
        const OpConstants constants = op_constants(ir_, instr);
        if (instr.dual) {
          std::array<std::array<TracedDual, 3>, max_op_args> args{};
          std::array<const TracedDual*, max_op_args> pointers{};
          for (int a = 0; a < instr.arg_count; ++a) {
            for (int c = 0; c < constants.arg_components[a]; ++c) args[a][c] = argument(instr.args[a], c);
            pointers[a] = args[a].data();
          }
          traced_dual_op(instr.op)(constants, pointers.data(), result.data());
        } else {
          std::array<std::array<TraceF, 3>, max_op_args> args{};
          std::array<const TraceF*, max_op_args> pointers{};
          for (int a = 0; a < instr.arg_count; ++a) {
            for (int c = 0; c < constants.arg_components[a]; ++c) args[a][c] = argument(instr.args[a], c).value;
            pointers[a] = args[a].data();
          }
          std::array<TraceF, 3> values;
          traced_op(instr.op)(constants, pointers.data(), values.data());
          for (int c = 0; c < count; ++c) result[c] = TracedDual(values[c]);
        }
        break;
      }
      case IrOpKind::constant:
        for (int c = 0; c < count; ++c)
          result[c] = TracedDual(TraceF(ir_.data[static_cast<std::size_t>(instr.data_offset + std::min(c, instr.data_count - 1))]));
        break;
      case IrOpKind::param:
        for (int c = 0; c < count; ++c) result[c] = TracedDual(TraceF::named(param_text(instr.immediate[0] + c)));
        break;
      case IrOpKind::global: {
        const GlobalDef& global = global_def(static_cast<GlobalId>(instr.immediate[0]));
        for (int c = 0; c < count; ++c) {
          const TraceF value = TraceF::named(component(std::string(global.name), global.components, c));
          // P's partials dP_c / dP_k are 1 where k = c.
          result[c] = instr.dual ? TracedDual(value, TraceF(c == 0 ? 1.0f : 0.0f), TraceF(c == 1 ? 1.0f : 0.0f),
                                              TraceF(c == 2 ? 1.0f : 0.0f))
                                 : TracedDual(value);
        }
        break;
      }
      case IrOpKind::extract: result[0] = values_[instr.args[0]][instr.immediate[0]]; break;
      case IrOpKind::partials: {
        const TracedDual& of = values_[instr.args[0]][0];
        result = {TracedDual(of.dx), TracedDual(of.dy), TracedDual(of.dz)};
        break;
      }
      default: break;
    }
    return result;
  }

  // The float a param's uniform gives for slot `slot` of the param block.
  std::string param_text(int slot) const {
    for (const IrParam& param : ir_.params) {
      const int count = component_count(param.type);
      if (slot < param.slot || slot >= param.slot + count) continue;
      const std::string name = uniform_names_.at(param.name);
      if (param.type == Type::int_) return "float(" + name + ")";
      if (param.type == Type::bool_) return "(" + name + " ? 1.0 : 0.0)";
      return component(name, count, slot - param.slot);
    }
    return "0.0";
  }

  // Names of the GLSL variables of value i, component c: its value and,
  // for a dual, its partials.
  static std::array<std::string, 4> variables(std::size_t i, int c) {
    const std::string name = "v" + std::to_string(i) + "_" + std::to_string(c);
    return {name, name + "_dx", name + "_dy", name + "_dz"};
  }

  Status trace_program() {
    // Values computed in a conditional region are declared before it, so
    // that what follows can read them (zero where it did not run).
    int depth = 0;
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.kind == IrOpKind::begin_region) ++depth;
      else if (instr.kind == IrOpKind::end_region) --depth;
      else if (depth > 0)
        for (int c = 0; c < components(static_cast<std::int32_t>(i)); ++c)
          for (int k = 0; k < (instr.dual ? 4 : 1); ++k) trace_.statement("float " + variables(i, c)[k] + " = 0.0;");
    }
    depth = 0;
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.kind == IrOpKind::begin_region) {
        trace_.statement("// the samples where node " + quoted_text(ir_.code[instr.args[0]].source) + " is " +
                         (instr.immediate[0] == 0 ? "true" : "false"));
        trace_.open("if (" + values_[instr.args[0]][0].value.text + (instr.immediate[0] == 0 ? " != " : " == ") +
                    "0.0)");
        ++depth;
        continue;
      }
      if (instr.kind == IrOpKind::end_region) {
        trace_.close();
        --depth;
        continue;
      }
      trace_.statement("// " + instruction_comment(instr));
      std::array<TracedDual, 3> result = evaluate(i);
      if (depth > 0) {
        for (int c = 0; c < components(static_cast<std::int32_t>(i)); ++c) {
          const std::array<std::string, 4> names = variables(i, c);
          TracedDual& part = result[c];
          TraceF* parts[4] = {&part.value, &part.dx, &part.dy, &part.dz};
          for (int k = 0; k < (instr.dual ? 4 : 1); ++k) {
            trace_.statement(names[k] + " = " + parts[k]->text + ";");
            *parts[k] = TraceF::named(names[k]);
          }
        }
      }
      values_[i] = result;
      if (trace_.statements() > max_glsl_statements)
        return refusal(i, "the GLSL of the program passes " + std::to_string(max_glsl_statements) +
                              " statements here, too many for a shader");
    }
    for (const IrOutput& output : ir_.outputs) {
      const int count = component_count(output.type);
      std::vector<std::string> parts;
      for (int c = 0; c < count; ++c) parts.push_back(argument(output.value, c).value.text);
      trace_.statement(output_name(output.id) + " = " + glsl_vector_type(count) + "(" +
                       joined(parts, [](const std::string& p) { return p; }) + ");");
    }
    return Done{};
  }

  static std::string output_name(OutputId id) { return "out_" + std::string(output_id_name(id)); }

  std::string header() const {
    std::ostringstream out;
    if (!options_.shadertoy) out << "#version 300 es\n";
    out << "// " << function_name_ << ": the " << graph_kind_name(ir_.kind) << " graph "
        << (graph_.file.empty() ? std::string("given") : quoted_text(graph_.file))
        << ", written by `shadetree emit --glsl" << (options_.shadertoy ? " --shadertoy" : "") << "`.\n";
    if (options_.shadertoy)
      out << "// Paste it into Shadertoy's Image tab. time is iTime; the frame is iTime * 24.\n";
    else
      out << "// GLSL ES 3.00 (WebGL 2); desktop GL 3.3 and later take it with \"#version 330 core\" as the\n"
          << "// first line. It computes what shadetree's interpreter computes, in the same operations;\n"
          << "// GPUs may round division, sqrt and fused multiply-adds differently (docs/glsl.md).\n";
    if (has_main() && !options_.shadertoy)
      out << "// Draw a full-screen triangle with st_resolution = the target's size in pixels and\n"
          << "// st_frame = the animation frame; st_fragment gets colour and alpha.\n";
    if (!has_main())
      out << "// Call " << function_name_ << " for each sample, with the globals its signature names, as\n"
          << "// shadetree's " << graph_kind_name(ir_.kind) << " driver does.\n";
    if (!options_.shadertoy) out << "precision highp float;\nprecision highp int;\n";
    return out.str();
  }

  std::string param_default(const IrParam& param) const {
    const int count = component_count(param.type);
    const float* values = param_block_.data() + param.slot;
    if (param.type == Type::int_) return lanes::glsl_int(static_cast<std::int32_t>(values[0]));
    if (param.type == Type::bool_) return values[0] != 0.0f ? "true" : "false";
    std::vector<float> parts(values, values + count);
    const std::string list = joined(parts, lanes::glsl_float);
    return count == 1 ? list : glsl_vector_type(count) + "(" + list + ")";
  }

  static std::string param_type(const IrParam& param) {
    if (param.type == Type::int_) return "int";
    if (param.type == Type::bool_) return "bool";
    return glsl_vector_type(component_count(param.type));
  }

  std::string uniforms() const {
    if (ir_.params.empty()) return "";
    std::ostringstream out;
    out << "\n// The graph's params" << (options_.shadertoy ? ", at their defaults" : "; the defaults are the graph's")
        << ".\n";
    for (const IrParam& param : ir_.params) {
      const std::string declaration = param_type(param) + " " + uniform_names_.at(param.name);
      if (options_.shadertoy)
        out << "const " << declaration << " = " << param_default(param) << ";  // param " << quoted_text(param.name)
            << "\n";
      else
        out << "uniform " << declaration << ";  // param " << quoted_text(param.name) << ", default "
            << param_default(param) << "\n";
    }
    return out.str();
  }

  std::string tables() const {
    std::ostringstream out;
    std::string comment;
    for (const GlslArray& array : arrays_) {
      if (!trace_.used(array.name)) continue;
      if (array.comment != comment) out << "\n// " << array.comment << "\n";
      comment = array.comment;
      out << "const " << array.type << " " << array.name << "[" << array.size << "] = " << array.type << "["
          << array.size << "](\n    " << array.values << ");\n";
    }
    return out.str();
  }

  std::string function() const {
    std::vector<std::string> parameters;
    for (GlobalId id : reads_) {
      const GlobalDef& global = global_def(id);
      parameters.push_back(glsl_vector_type(global.components) + " " + std::string(global.name));
    }
    for (const IrOutput& output : ir_.outputs)
      parameters.push_back("out " + glsl_vector_type(component_count(output.type)) + " " + output_name(output.id));
    std::ostringstream out;
    out << "\nvoid " << function_name_ << "(" << joined(parameters, [](const std::string& p) { return p; })
        << ") {\n"
        << trace_.text() << "}\n";
    return out.str();
  }

  // Whether the kind's driver is a plain image the fragment shader can be:
  // a texture's domain or an environment's panorama.
  bool has_main() const { return ir_.kind == GraphKind::texture || ir_.kind == GraphKind::environment; }

  // The arguments of the function for the globals it reads, named as
  // pixel_globals() declares them.
  std::string call() const {
    std::vector<std::string> arguments;
    for (GlobalId id : reads_) {
      switch (id) {
        case GlobalId::time: arguments.push_back(std::string("st_frame / ") + frames_per_second_literal); break;
        case GlobalId::frame: arguments.push_back("st_frame"); break;
        default: arguments.push_back("st_" + std::string(global_def(id).name)); break;
      }
    }
    std::string text = function_name_ + "(" + joined(arguments, [](const std::string& a) { return a; });
    for (const IrOutput& output : ir_.outputs) text += ", " + output_name(output.id);
    return text + ");";
  }

  std::string output_declarations() const {
    std::string text;
    for (const IrOutput& output : ir_.outputs)
      text += "  " + glsl_vector_type(component_count(output.type)) + " " + output_name(output.id) + ";\n";
    return text;
  }

  std::string alpha_text() const {
    for (const IrOutput& output : ir_.outputs)
      if (output.id == OutputId::alpha) return output_name(OutputId::alpha);
    return "1.0";
  }

  // The globals of the pixel at `coordinate` (gl_FragCoord.xy) of an image
  // of `size`, as the kind's driver gives them, then the call.
  std::string pixel_globals(const std::string& coordinate, const std::string& size) const {
    return (ir_.kind == GraphKind::texture ? texture_pixel(coordinate, size) : environment_pixel(coordinate, size)) +
           output_declarations() + "  " + call() + "\n";
  }

  // As render/texture_driver.cpp places it: u, v from the pixel centre
  // (rows counted from the top), P through the graph's domain, N facing
  // the viewer, filter_width a pixel's size.
  std::string texture_pixel(const std::string& coordinate, const std::string& size) const {
    const RenderSettings& render = graph_.render;
    std::ostringstream out;
    out << "  const vec2 st_domain_min = vec2(" << lanes::glsl_float(render.domain_min[0]) << ", "
        << lanes::glsl_float(render.domain_min[1]) << ");\n"
        << "  const vec2 st_domain_max = vec2(" << lanes::glsl_float(render.domain_max[0]) << ", "
        << lanes::glsl_float(render.domain_max[1]) << ");\n"
        << "  float st_u = " << coordinate << ".x / " << size << ".x;\n"
        << "  float st_v = 1.0 - (" << size << ".y - " << coordinate << ".y) / " << size << ".y;\n"
        << "  vec3 st_P = vec3(st_domain_min.x + st_u * (st_domain_max.x - st_domain_min.x),\n"
        << "                   st_domain_min.y + st_v * (st_domain_max.y - st_domain_min.y), "
        << lanes::glsl_float(render.z) << ");\n"
        << "  vec3 st_N = vec3(0.0, 0.0, 1.0);\n"
        << "  vec2 st_uv = vec2(st_u, st_v);\n"
        << "  vec2 st_span = st_domain_max - st_domain_min;\n"
        << "  float st_filter_width = max(abs(st_span.x) / " << size << ".x, abs(st_span.y) / " << size << ".y);\n";
    return out.str();
  }

  // As render/environment_driver.cpp: a latitude-longitude panorama,
  // longitude 0 down -z growing toward +x, latitude +90 degrees on the top
  // row; I the direction, P the same point of the unit sphere, N = -I, uv
  // longitude and latitude in [0, 1], filter_width the angle of a pixel.
  // GLSL's sin, cos, atan and asin stand for the C library's here.
  std::string environment_pixel(const std::string& coordinate, const std::string& size) const {
    const std::string pi = lanes::glsl_float(3.14159265358979f);
    std::ostringstream out;
    out << "  float st_longitude = 2.0 * " << pi << " * " << coordinate << ".x / " << size << ".x - " << pi << ";\n"
        << "  float st_latitude = 0.5 * " << pi << " - " << pi << " * (" << size << ".y - " << coordinate << ".y) / "
        << size << ".y;\n"
        << "  vec3 st_I = vec3(sin(st_longitude) * cos(st_latitude), sin(st_latitude), "
           "-cos(st_longitude) * cos(st_latitude));\n"
        << "  vec3 st_P = st_I;\n"
        << "  vec3 st_N = -st_I;\n"
        << "  vec2 st_uv = vec2((atan(st_I.x, -st_I.z) + " << pi << ") / (2.0 * " << pi << "), asin(clamp(st_I.y, -1.0, "
        << "1.0)) / " << pi << " + 0.5);\n"
        << "  float st_filter_width = " << pi << " / " << size << ".y;\n";
    return out.str();
  }

  std::string image_main() const {
    std::ostringstream out;
    out << "\nuniform vec2 st_resolution;  // the image, in pixels\n"
        << "uniform float st_frame;      // the animation frame\n"
        << "out vec4 st_fragment;\n\n"
        << "void main() {\n"
        << pixel_globals("gl_FragCoord", "st_resolution") << "  st_fragment = vec4(out_color, " << alpha_text()
        << ");\n}\n";
    return out.str();
  }

  std::string shadertoy_main() const {
    std::ostringstream out;
    out << "\nvoid mainImage(out vec4 fragColor, in vec2 fragCoord) {\n  float st_frame = iTime * "
        << frames_per_second_literal << ";\n"
        << pixel_globals("fragCoord", "iResolution.xy") << "  fragColor = vec4(out_color, 1.0);\n}\n";
    return out.str();
  }

  const Graph& graph_;
  const ShadeIR& ir_;
  const std::vector<float>& param_block_;
  const GlslOptions& options_;
  std::vector<std::array<TracedDual, 3>> values_;
  std::string function_name_;
  std::map<std::string, std::string> uniform_names_;  // param name -> its uniform
  std::set<GlobalId> reads_;
  std::set<int> seeds_;
  struct GlslArray {
    std::string name, comment, type, size, values;
  };
  std::vector<GlslArray> arrays_;  // in the order they are declared
  lanes::Trace trace_;
};

}  // namespace

Result<GlslShader> emit_glsl(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                             const GlslOptions& options) {
  return GlslEmitter(graph, ir, param_block, options).emit();
}

}  // namespace shadetree
