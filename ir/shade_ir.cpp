#include "ir/shade_ir.h"

#include <algorithm>
#include <sstream>

#include "graph/diagnostic.h"
#include "graph/generated_names.h"
#include "nodes/registry.h"

namespace shadetree {

void reorder_shade_ir(ShadeIR& ir, const std::vector<std::int32_t>& order) {
  std::vector<std::int32_t> new_index(ir.code.size(), -1);
  std::vector<IrInstr> code;
  code.reserve(order.size());
  for (std::int32_t old_index : order) {
    new_index[old_index] = static_cast<std::int32_t>(code.size());
    IrInstr instr = ir.code[old_index];
    for (int a = 0; a < instr.arg_count; ++a) instr.args[a] = new_index[instr.args[a]];
    if (instr.kind == IrOpKind::begin_region) instr.immediate[1] = -1;
    code.push_back(std::move(instr));
  }
  for (IrOutput& output : ir.outputs) output.value = new_index[output.value];
  ir.code = std::move(code);
}

int stored_components(const IrInstr& instr) { return component_count(instr.type) * (instr.dual ? 4 : 1); }

Type argument_type(const IrInstr& instr, int a) {
  const PortSpec& port = op_def(instr.op).inputs[static_cast<std::size_t>(a)];
  return port.rule == TypeRule::generic ? instr.generic : port.type;
}

std::string instruction_comment(const IrInstr& instr) {
  std::string text;
  switch (instr.kind) {
    case IrOpKind::op: text = op_def(instr.op).name; break;
    case IrOpKind::constant: text = "constant"; break;
    case IrOpKind::param: text = "param"; break;
    case IrOpKind::global: text = std::string(global_def(static_cast<GlobalId>(instr.immediate[0])).name); break;
    case IrOpKind::extract: text = "component " + std::to_string(instr.immediate[0]); break;
    case IrOpKind::partials: text = "gradient"; break;
    default: break;
  }
  if (instr.dual) text += ", with its gradient";
  if (!instr.source.empty()) text += ", node " + quoted_text(instr.source);
  return text;
}

std::string program_key_text(const ShadeIR& ir) {
  std::ostringstream text;
  for (const IrInstr& instr : ir.code) {
    text << static_cast<int>(instr.kind) << ' ' << static_cast<int>(instr.op) << ' ' << static_cast<int>(instr.type)
         << ' ' << static_cast<int>(instr.generic) << ' ' << instr.uniform << ' ' << instr.dual << ' ' << instr.data_offset << ' '
         << instr.data_count << ' ' << instr.immediate[0] << ' ' << instr.immediate[1];
    for (int a = 0; a < instr.arg_count; ++a) text << ' ' << instr.args[a];
    text << '\n';
  }
  text.write(reinterpret_cast<const char*>(ir.data.data()), static_cast<std::streamsize>(ir.data.size() * sizeof(float)));
  text << "kind " << static_cast<int>(ir.kind) << '\n';
  for (const IrOutput& output : ir.outputs)
    text << "out " << static_cast<int>(output.id) << ' ' << output.value << ' ' << static_cast<int>(output.type) << '\n';
  return text.str();
}

std::string format_shade_ir(const ShadeIR& ir) {
  std::ostringstream text;
  for (const IrParam& param : ir.params)
    text << "param " << param.name << ": " << type_name(param.type) << " @" << param.slot << "\n";
  int depth = 0;
  for (std::size_t i = 0; i < ir.code.size(); ++i) {
    const IrInstr& instr = ir.code[i];
    if (instr.kind == IrOpKind::end_region) --depth;
    text << std::string(static_cast<std::size_t>(2 * depth), ' ') << "%" << i << " = ";
    switch (instr.kind) {
      case IrOpKind::op: text << op_def(instr.op).name; break;
      case IrOpKind::constant: text << "const"; break;
      case IrOpKind::param: text << "param"; break;
      case IrOpKind::global: text << global_def(static_cast<GlobalId>(instr.immediate[0])).name; break;
      case IrOpKind::extract: text << "extract." << "xyz"[instr.immediate[0]]; break;
      case IrOpKind::begin_region: text << (instr.immediate[0] ? "region unless" : "region if"); break;
      case IrOpKind::end_region: text << "end region"; break;
      case IrOpKind::partials: text << "partials"; break;
    }
    if (instr.kind != IrOpKind::end_region && instr.kind != IrOpKind::begin_region)
      text << " " << (instr.dual ? "dual " : "") << type_name(instr.type);
    for (int a = 0; a < instr.arg_count; ++a) text << (a ? ", " : " ") << "%" << instr.args[a];
    if (instr.kind == IrOpKind::constant) {
      text << " [";
      for (int c = 0; c < instr.data_count; ++c) text << (c ? ", " : "") << ir.data[instr.data_offset + c];
      text << "]";
    }
    if (instr.kind == IrOpKind::param) text << " @" << instr.immediate[0];
    if (instr.uniform && (instr.kind == IrOpKind::op || instr.kind == IrOpKind::global)) text << "  uniform";
    if (!instr.source.empty()) text << "  ; " << printable(instr.source);  // a node id may hold a line break
    text << "\n";
    if (instr.kind == IrOpKind::begin_region) ++depth;
  }
  for (const IrOutput& output : ir.outputs)
    text << "output " << output_id_name(output.id) << ": " << type_name(output.type) << " = %" << output.value << "\n";
  return text.str();
}

}  // namespace shadetree

