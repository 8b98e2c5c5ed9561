#include "cppgen/emit_cpp.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "cppgen/library_source.h"
#include "graph/generated_names.h"
#include "nodes/globals.h"
#include "nodes/noise_tables.h"
#include "nodes/output_contract.h"
#include "nodes/registry.h"

namespace shadetree {
namespace {

// A float literal that reads back as exactly `value`.
std::string float_literal(float value) {
  if (std::isnan(value)) return "std::numeric_limits<float>::quiet_NaN()";
  if (std::isinf(value)) return value > 0 ? "std::numeric_limits<float>::infinity()" : "-std::numeric_limits<float>::infinity()";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  std::string literal = text;
  if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
  return literal + "f";
}

// A number for a comment.
std::string readable(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(value));
  return text;
}

template <class Values, class Format>
std::string list(const Values& values, Format format) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += (i % 8 == 0) ? ",\n    " : ", ";
    text += format(values[i]);
  }
  return text;
}

std::string c_type(Type type) {
  switch (type) {
    case Type::int_: return "int";
    case Type::bool_: return "bool";
    default: return "float";
  }
}

// The op library's source is written between these lines.
constexpr const char* library_begin = "#ifndef SHADETREE_EMITTED_LIBRARY";
constexpr const char* library_end = "#endif  // SHADETREE_EMITTED_LIBRARY";

// The pieces the emitter writes, for one program.
class CppEmitter {
 public:
  CppEmitter(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block, std::string name)
      : graph_(graph), ir_(ir), param_block_(param_block), name_(std::move(name)) {
    IdentifierScope fields;
    for (const IrParam& param : ir_.params) param_fields_[param.name] = fields.add(param.name);
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.kind == IrOpKind::global) reads_.insert(static_cast<GlobalId>(instr.immediate[0]));
      for (int a = 0; a < instr.arg_count; ++a)
        if (!instr.uniform && ir_.code[instr.args[a]].uniform) uniform_used_.insert(instr.args[a]);
    }
    for (const IrOutput& output : ir_.outputs)
      if (ir_.code[output.value].uniform) uniform_used_.insert(output.value);
  }

  Result<std::string> emit() {
    if (ir_.data.size() > max_emitted_data) {
      std::size_t largest = 0;
      for (std::size_t i = 1; i < ir_.code.size(); ++i)
        if (ir_.code[i].data_count > ir_.code[largest].data_count) largest = i;
      Diagnostic error = invalid_input("op \"" + op_def(ir_.code[largest].op).name + "\" holds " +
                                       std::to_string(ir_.code[largest].data_count) +
                                       " floats of data, too many to emit as C++ source (at most " +
                                       std::to_string(max_emitted_data) + " in all)");
      error.file = graph_.file;
      error.node = ir_.code[largest].source;
      return error;
    }
    std::ostringstream out;
    out << header() << no_contraction_begin() << library() << "\n" << interface() << "\n" << constants() << "\n"
        << uniform_function() << "\n" << block_function() << "\n" << run_function() << no_contraction_end();
    return out.str();
  }

 private:
  std::string value_name(std::int32_t value) const {
    const std::string& source = ir_.code[value].source;
    return "v" + std::to_string(value) + (source.empty() ? "" : "_" + code_identifier(source));
  }
  // Value v in the code of the block: a register of its own, or, for a
  // uniform value, its splatted copy.
  int components(std::int32_t value) const { return component_count(ir_.code[value].type); }
  // The lanes of value i's register in the block: F, or duals of F.
  std::string register_type(std::size_t i) const { return ir_.code[i].dual ? "lanes::Dual<F>" : "F"; }

  std::string header() const {
    std::ostringstream out;
    out << "// " << name_ << ": the kernel of " << (graph_.file.empty() ? "a graph" : quoted_text(graph_.file))
        << ", written by `shadetree emit --cpp`.\n"
        << "// Standalone C++17 (the standard library only). Its SIMD width follows the target it is\n"
        << "// compiled for (16 lanes with AVX-512, 8 with AVX, 4 with SSE2 or NEON); define\n"
        << "// SHADETREE_NO_SIMD for one sample at a time. It computes what shadetree's interpreter\n"
        << "// computes, with the same operations (multiplies and adds are never fused).\n//\n"
        << "//   " << name_ << "_params params;            // the graph's defaults\n"
        << "//   " << name_ << "_inputs inputs{...};       // planes of `count` floats\n"
        << "//   " << name_ << "_outputs outputs{...};\n"
        << "//   " << name_ << "_run(&params, &inputs, &outputs, count);\n"
        << "#pragma once\n\n"
        << library_includes() << "#include <cstddef>\n#include <initializer_list>\n#include <limits>\n\n";
    return out.str();
  }

  // The op library once per translation unit, whatever number of kernels
  // it includes, in a namespace of its own.
  static std::string library() {
    std::ostringstream out;
    out << library_begin << "\n#define SHADETREE_EMITTED_LIBRARY\n"
        << "namespace shadetree_emitted {\n"
        << library_source()
        << "namespace shadetree {\n"
        << "// One instruction: the op's semantics over a frame of lane arrays.\n"
        << "template <class Op, class F>\n"
        << "inline void evaluate(F* result, const OpConstants& constants, std::initializer_list<const F*> args) {\n"
        << "  const F* arguments[max_op_args] = {};\n"
        << "  int a = 0;\n"
        << "  for (const F* arg : args) arguments[a++] = arg;\n"
        << "  Op::evaluate(VectorFrame<F>{{&constants}, arguments, result});\n"
        << "}\n"
        << "// One dual instruction: its value and gradient with respect to P.\n"
        << "template <class Op, class F>\n"
        << "inline void evaluate_dual(lanes::Dual<F>* result, const OpConstants& constants,\n"
        << "                          std::initializer_list<const lanes::Dual<F>*> args) {\n"
        << "  const lanes::Dual<F>* arguments[max_op_args] = {};\n"
        << "  int a = 0;\n"
        << "  for (const lanes::Dual<F>* arg : args) arguments[a++] = arg;\n"
        << "  Op::evaluate(DualVectorFrame<F>{{&constants}, arguments, result});\n"
        << "}\n"
        << "}  // namespace shadetree\n"
        << "}  // namespace shadetree_emitted\n" << library_end << "\n";
    return out.str();
  }

  // Multiplies and adds are not fused into FMAs (which GCC does by default
  // with -march=native): the interpreter and the JIT round each one, and a
  // fused one changes, for example, sin's range reduction at 1e4 by 1e-2.
  // Scoped to the emitted code, not the includer's; all of it, since GCC
  // does not inline across different optimization options.
  static std::string no_contraction_begin() {
    return "#if defined(__clang__)\n#pragma float_control(push)\n#pragma clang fp contract(off)\n"
           "#elif defined(__GNUC__)\n#pragma GCC push_options\n#pragma GCC optimize(\"fp-contract=off\")\n#endif\n";
  }
  static std::string no_contraction_end() {
    return "#if defined(__clang__)\n#pragma float_control(pop)\n#elif defined(__GNUC__)\n#pragma GCC pop_options\n#endif\n";
  }

  const ParamDecl* param_decl(const std::string& name) const {
    for (const ParamDecl& decl : graph_.params)
      if (decl.name == name) return &decl;
    return nullptr;
  }

  std::string interface() const {
    std::ostringstream out;
    out << "// The graph's params; the values are its defaults.\nstruct " << name_ << "_params {\n";
    for (const IrParam& param : ir_.params) {
      const int count = component_count(param.type);
      std::vector<std::string> values;
      for (int c = 0; c < count; ++c) {
        const float value = param_block_[static_cast<std::size_t>(param.slot + c)];
        values.push_back(param.type == Type::int_    ? std::to_string(static_cast<int>(value))
                         : param.type == Type::bool_ ? (value != 0.0f ? "true" : "false")
                                                     : float_literal(value));
      }
      out << "  " << c_type(param.type) << " " << param_fields_.at(param.name);
      if (count > 1) out << "[" << count << "]";
      out << " = " << (count > 1 ? "{" : "") << list(values, [](const std::string& v) { return v; })
          << (count > 1 ? "}" : "") << ";  // " << type_name(param.type);
      if (param_fields_.at(param.name) != param.name) out << " param " << quoted_text(param.name);
      if (const ParamDecl* decl = param_decl(param.name)) {
        if (decl->min || decl->max)
          out << " in [" << (decl->min ? readable(*decl->min) : "-inf") << ", "
              << (decl->max ? readable(*decl->max) : "inf") << "]";
        if (!decl->doc.empty()) out << ": " << quoted_text(decl->doc);
      }
      out << "\n";
    }
    out << "};\n\n// What the program reads: a plane of floats per component of each varying\n"
        << "// global (count floats from the pointer), one value per uniform global.\n"
        << "struct " << name_ << "_inputs {\n";
    for (GlobalId id : reads_) {
      const GlobalDef& global = global_def(id);
      if (global.variability == Variability::varying)
        out << "  const float* " << global.name
            << (global.components > 1 ? "[" + std::to_string(global.components) + "] = {}" : " = nullptr") << ";  // "
            << global.doc << "\n";
      else
        out << "  float " << global.name << (global.components > 1 ? "[" + std::to_string(global.components) + "]" : "")
            << " = {};  // " << global.doc << "\n";
    }
    out << "};\n\n// A plane per component of each output; a null plane is not written.\n"
        << "struct " << name_ << "_outputs {\n";
    for (const IrOutput& output : ir_.outputs)
      out << "  float* " << output_id_name(output.id) << "[" << component_count(output.type) << "] = {};  // "
          << type_name(output.type) << "\n";
    out << "};\n";
    return out.str();
  }

  std::string constants() const {
    std::ostringstream out;
    out << "namespace " << name_ << "_detail {\nusing namespace shadetree_emitted::shadetree;\n\n";
    out << "// Attribute data (spline knots, tables, images) of the ops.\ninline constexpr float data[] = {\n    "
        << (ir_.data.empty() ? std::string("0.0f") : list(ir_.data, float_literal)) << "};\n\n";
    std::set<int> seeds;
    for (const IrInstr& instr : ir_.code)
      if (instr.kind == IrOpKind::op && op_def(instr.op).tables == OpTables::noise) seeds.insert(instr.immediate[0]);
    for (int seed : seeds) {
      const NoiseTables& tables = noise_tables(static_cast<std::uint32_t>(seed));
      auto ints = [](std::int32_t v) { return std::to_string(v); };
      out << "// Perlin & Hoffert 1989 section 2.3: the noise tables of seed " << seed << ".\n"
          << "inline constexpr NoiseTables tables_" << seed << " = {\n    {{"
          << list(tables.hashed_gradient_xyzw, float_literal) << "}},\n    {{" << list(tables.permutation, ints)
          << "}},\n";
      for (const auto* table : {&tables.gradient_x, &tables.gradient_y, &tables.gradient_z, &tables.hashed_gradient_x,
                                &tables.hashed_gradient_y, &tables.hashed_gradient_z})
        out << "    {{" << list(*table, float_literal) << "}},\n";
      out << "};\n\n";
    }
    out << "// What each op instruction fixes at compile time (nodes/op_frame.h).\n";
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.kind != IrOpKind::op) continue;
      std::vector<int> arg_components(max_op_args, 0);
      for (int a = 0; a < instr.arg_count; ++a) arg_components[a] = component_count(argument_type(instr, a));
      const bool tables = op_def(instr.op).tables == OpTables::noise;
      out << "inline constexpr OpConstants k" << i << "{"
          << (instr.data_count > 0 ? "data + " + std::to_string(instr.data_offset) : "nullptr") << ", "
          << (tables ? "&tables_" + std::to_string(instr.immediate[0]) : "nullptr") << ", " << instr.data_count
          << ", {" << instr.immediate[0] << ", " << instr.immediate[1] << "}, " << component_count(instr.type) << ", {"
          << list(arg_components, [](int v) { return std::to_string(v); }) << "}};\n";
    }
    out << "\n// The uniform values: computed once per call.\nstruct Uniforms {\n";
    for (std::size_t i = 0; i < ir_.code.size(); ++i)
      if (ir_.code[i].uniform && ir_.code[i].kind != IrOpKind::begin_region && ir_.code[i].kind != IrOpKind::end_region)
        out << "  float " << value_name(static_cast<std::int32_t>(i)) << "[" << components(static_cast<std::int32_t>(i))
            << "];\n";
    out << "};\n";
    return out.str();
  }

  // Op instruction i, with each scalar that it reads for a vector splatted
  // into a temporary of its own first; in the uniform pass registers are
  // fields of `u`.
  std::string op_statement(std::size_t i, const std::string& lane, const std::string& indent,
                           bool uniform_pass) const {
    const IrInstr& instr = ir_.code[i];
    std::ostringstream out;
    std::vector<std::string> args;
    for (int a = 0; a < instr.arg_count; ++a) {
      const std::int32_t value = instr.args[a];
      std::string name = (uniform_pass ? "u." : "") + value_name(value);
      const int wanted = component_count(argument_type(instr, a));
      if (instr.dual && !ir_.code[value].dual) {
        // A value that does not depend on P, read with zero partials.
        const std::string lifted = "dual" + std::to_string(i) + "_" + std::to_string(a);
        out << indent << "const lanes::Dual<F> " << lifted << "[" << wanted << "] = {"
            << list(std::vector<int>(static_cast<std::size_t>(wanted), 0),
                    [&, c = 0](int) mutable {
                      return "lanes::Dual<F>(" + name + "[" + std::to_string(std::min(c++, components(value) - 1)) + "])";
                    })
            << "};\n";
        name = lifted;
      } else if (components(value) < wanted) {
        const std::string splat = "splat" + std::to_string(i) + "_" + std::to_string(a);
        out << indent << "const " << (instr.dual ? register_type(i) : lane) << " " << splat << "[" << wanted << "] = {"
            << list(std::vector<int>(static_cast<std::size_t>(wanted), 0), [&](int) { return name + "[0]"; })
            << "};\n";
        name = splat;
      }
      args.push_back(name);
    }
    const std::string result = (uniform_pass ? "u." : "") + value_name(static_cast<std::int32_t>(i));
    out << indent << (instr.dual ? "evaluate_dual<ops::" : "evaluate<ops::") << op_symbol(instr.op) << ">(" << result << ", k" << i << ", {"
        << list(args, [](const std::string& v) { return v; }) << "});\n";
    return out.str();
  }

  std::string comment(std::size_t i) const { return "  // " + instruction_comment(ir_.code[i]) + "\n"; }

  // One instruction outside the op library: a constant, param, global,
  // component or gradient, into `target`.
  std::string simple_statement(std::size_t i, const std::string& target, bool uniform_pass) const {
    const IrInstr& instr = ir_.code[i];
    const int count = components(static_cast<std::int32_t>(i));
    std::vector<std::string> values;
    for (int c = 0; c < count; ++c) {
      std::string value;
      switch (instr.kind) {
        case IrOpKind::constant:
          value = float_literal(ir_.data[static_cast<std::size_t>(instr.data_offset + std::min(c, instr.data_count - 1))]);
          break;
        case IrOpKind::param: {
          const IrParam* param = nullptr;
          for (const IrParam& candidate : ir_.params)
            if (instr.immediate[0] >= candidate.slot &&
                instr.immediate[0] < candidate.slot + component_count(candidate.type))
              param = &candidate;
          const int component = instr.immediate[0] - param->slot + c;
          value = "params." + param_fields_.at(param->name) +
                  (component_count(param->type) > 1 ? "[" + std::to_string(component) + "]" : "");
          if (param->type == Type::int_) value = "static_cast<float>(" + value + ")";
          if (param->type == Type::bool_) value = "(" + value + " ? 1.0f : 0.0f)";
          break;
        }
        case IrOpKind::global: {
          const GlobalDef& global = global_def(static_cast<GlobalId>(instr.immediate[0]));
          const std::string field =
              "inputs." + std::string(global.name) + (global.components > 1 ? "[" + std::to_string(c) + "]" : "");
          value = uniform_pass ? field : "lanes::load<F>(" + field + " + i)";
          if (instr.dual) {  // P, whose partials dP_c / dP_k are 1 where k = c
            auto unit = [&](int k) { return std::string(k == c ? "lanes::splat<F>(1.0f)" : "lanes::splat<F>(0.0f)"); };
            value = "lanes::Dual<F>(" + value + ", " + unit(0) + ", " + unit(1) + ", " + unit(2) + ")";
          }
          break;
        }
        case IrOpKind::extract:
          value = (uniform_pass ? "u." : "") + value_name(instr.args[0]) + "[" + std::to_string(instr.immediate[0]) + "]";
          break;
        case IrOpKind::partials:
          value = value_name(instr.args[0]) + "[0].d" + "xyz"[c];
          break;
        default: break;
      }
      if (!uniform_pass && instr.kind != IrOpKind::global && instr.kind != IrOpKind::extract &&
          instr.kind != IrOpKind::partials)
        value = "lanes::splat<F>(" + value + ")";
      values.push_back(value);
    }
    return "  " + target + " = {" + list(values, [](const std::string& v) { return v; }) + "};\n";
  }

  std::string uniform_function() const {
    std::ostringstream out;
    out << "inline void uniforms(const " << name_ << "_params& params, const " << name_
        << "_inputs& inputs, Uniforms& u) {\n  (void)params;\n  (void)inputs;\n";
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (!instr.uniform || instr.kind == IrOpKind::begin_region || instr.kind == IrOpKind::end_region) continue;
      out << comment(i);
      if (instr.kind == IrOpKind::op) {
        out << op_statement(i, "float", "  ", true);
      } else {
        // Arrays are not assignable: one component at a time.
        std::string statement = simple_statement(i, "const float value[]", true);
        out << "  {\n  " << statement << "    std::copy(value, value + " << components(static_cast<std::int32_t>(i))
            << ", u." << value_name(static_cast<std::int32_t>(i)) << ");\n  }\n";
      }
    }
    out << "}\n";
    return out.str();
  }

  std::string block_function() const {
    std::ostringstream out;
    out << "// Samples [i, i + lanes of F): F is float (one sample) or lanes::floatv.\n"
        << "template <class F>\ninline void block(const Uniforms& u, const " << name_ << "_inputs& inputs, const "
        << name_ << "_outputs& outputs, std::size_t i) {\n  (void)u;\n  (void)inputs;\n";
    for (std::int32_t value : uniform_used_)
      out << "  const F " << value_name(value) << "[" << components(value) << "] = {"
          << list(std::vector<int>(static_cast<std::size_t>(components(value)), 0),
                  [&, c = 0](int) mutable { return "lanes::splat<F>(u." + value_name(value) + "[" + std::to_string(c++) + "])"; })
          << "};\n";
    // Values computed in a conditional region are declared before it, so
    // that the selects after it can read them (zero where it did not run).
    int depth = 0;
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      if (instr.kind == IrOpKind::begin_region) ++depth;
      else if (instr.kind == IrOpKind::end_region) --depth;
      else if (depth > 0 && !instr.uniform)
        out << "  " << register_type(i) << " " << value_name(static_cast<std::int32_t>(i)) << "["
            << components(static_cast<std::int32_t>(i))
            << "] = {};\n";
    }
    depth = 0;
    for (std::size_t i = 0; i < ir_.code.size(); ++i) {
      const IrInstr& instr = ir_.code[i];
      const std::string indent(2 + 2 * depth, ' ');
      if (instr.kind == IrOpKind::begin_region) {
        out << indent << "// the samples where node " << quoted_text(ir_.code[instr.args[0]].source) << " is "
            << (instr.immediate[0] == 0 ? "true" : "false") << "\n"
            << indent << "if (lanes::any(" << value_name(instr.args[0]) << "[0] "
            << (instr.immediate[0] == 0 ? "!=" : "==") << " 0.0f)) {\n";
        ++depth;
        continue;
      }
      if (instr.kind == IrOpKind::end_region) {
        --depth;
        out << std::string(2 + 2 * depth, ' ') << "}\n";
        continue;
      }
      if (instr.uniform) continue;
      out << indent << comment(i).substr(2);
      const std::string name = value_name(static_cast<std::int32_t>(i));
      const std::string declaration =
          depth > 0 ? "" : register_type(i) + " " + name + "[" + std::to_string(components(static_cast<std::int32_t>(i))) + "]";
      if (instr.kind == IrOpKind::op) {
        if (depth == 0) out << indent << declaration << ";\n";
        out << op_statement(i, "F", indent, false);
      } else if (depth == 0) {
        out << indent << simple_statement(i, declaration, false).substr(2);
      } else {
        std::string statement = simple_statement(i, "const " + register_type(i) + " value[]", false);
        out << indent << "{\n" << indent << statement << indent << "  std::copy(value, value + "
            << components(static_cast<std::int32_t>(i)) << ", " << name << ");\n" << indent << "}\n";
      }
    }
    for (const IrOutput& output : ir_.outputs) {
      const std::string field = "outputs." + std::string(output_id_name(output.id));
      for (int c = 0; c < component_count(output.type); ++c)
        out << "  if (" << field << "[" << c << "]) lanes::store(" << field << "[" << c << "] + i, "
            << value_name(output.value) << "[" << std::min(c, components(output.value) - 1) << "]);\n";
    }
    out << "}\n}  // namespace " << name_ << "_detail\n";
    return out.str();
  }

  std::string run_function() const {
    std::ostringstream out;
    out << "inline void " << name_ << "_run(const " << name_ << "_params* params, const " << name_
        << "_inputs* inputs, " << name_ << "_outputs* outputs, std::size_t count) {\n"
        << "  using namespace " << name_ << "_detail;\n"
        << "  Uniforms u;\n  uniforms(*params, *inputs, u);\n  std::size_t i = 0;\n"
        << "#ifdef SHADETREE_SIMD_WIDTH\n"
        << "  for (; i + lanes::simd_width <= count; i += lanes::simd_width) block<lanes::floatv>(u, *inputs, *outputs, i);\n"
        << "#endif\n"
        << "  for (; i < count; ++i) block<float>(u, *inputs, *outputs, i);\n}\n";
    return out.str();
  }

  const Graph& graph_;
  const ShadeIR& ir_;
  const std::vector<float>& param_block_;
  std::string name_;
  std::map<std::string, std::string> param_fields_;  // param name -> its field in NAME_params
  std::set<GlobalId> reads_;
  std::set<std::int32_t> uniform_used_;  // uniform values the block reads
};

}  // namespace

std::string emitted_program(const std::string& source) {
  const std::size_t begin = source.find(library_begin), end = source.find(library_end);
  if (begin == std::string::npos || end == std::string::npos) return source;
  return source.substr(0, begin) + source.substr(end + std::strlen(library_end));
}

Result<std::string> emit_cpp(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                             const std::string& name) {
  return CppEmitter(graph, ir, param_block, code_identifier(name, "kernel")).emit();
}

}  // namespace shadetree
