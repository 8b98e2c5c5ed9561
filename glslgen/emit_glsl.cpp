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

  Result<GlslFunction> emit() {
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
    GlslFunction result;
    result.name = function_name_;
    result.declarations = uniforms() + tables() + function();
    result.reads.assign(reads_.begin(), reads_.end());
    for (const IrOutput& output : ir_.outputs) result.outputs.push_back({output.id, component_count(output.type)});
    if (!options_.shadertoy)
      for (const IrParam& param : ir_.params)
        result.uniforms.push_back({param.name, uniform_names_.at(param.name), param_type(param), param.slot,
                                   component_count(param.type)});
    return result;
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
      trace_.statement(glsl_output_name(output.id) + " = " + glsl_vector_type(count) + "(" +
                       joined(parts, [](const std::string& p) { return p; }) + ");");
    }
    return Done{};
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
      parameters.push_back("out " + glsl_vector_type(component_count(output.type)) + " " + glsl_output_name(output.id));
    std::ostringstream out;
    out << "\nvoid " << function_name_ << "(" << joined(parameters, [](const std::string& p) { return p; })
        << ") {\n"
        << trace_.text() << "}\n";
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

std::string glsl_output_name(OutputId id) { return "out_" + std::string(output_id_name(id)); }

std::string glsl_vector_type(int components) {
  return components == 1 ? "float" : "vec" + std::to_string(components);
}

std::string GlslFunction::output_declarations(const std::string& indent) const {
  std::string text;
  for (const Output& output : outputs)
    text += indent + glsl_vector_type(output.components) + " " + glsl_output_name(output.id) + ";\n";
  return text;
}

std::string GlslFunction::call(const std::function<std::string(GlobalId)>& argument) const {
  std::vector<std::string> arguments;
  for (GlobalId id : reads) arguments.push_back(argument(id));
  for (const Output& output : outputs) arguments.push_back(glsl_output_name(output.id));
  std::string text = name + "(";
  for (std::size_t i = 0; i < arguments.size(); ++i) text += (i > 0 ? ", " : "") + arguments[i];
  return text + ");";
}

bool GlslFunction::writes(OutputId id) const {
  return std::any_of(outputs.begin(), outputs.end(), [&](const Output& output) { return output.id == id; });
}

Result<GlslFunction> emit_glsl_function(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                                        const GlslOptions& options) {
  return GlslEmitter(graph, ir, param_block, options).emit();
}

}  // namespace shadetree
