#include "ir/shade_ir.h"

#include <algorithm>

#include <sstream>

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
      case IrOpKind::extract: text << "extract." << "xyz"[instr.immediate[0]]; break;
      case IrOpKind::begin_region: text << (instr.immediate[0] ? "region unless" : "region if"); break;
      case IrOpKind::end_region: text << "end region"; break;
    }
    if (instr.kind != IrOpKind::end_region && instr.kind != IrOpKind::begin_region)
      text << " " << type_name(instr.type);
    for (int a = 0; a < instr.arg_count; ++a) text << (a ? ", " : " ") << "%" << instr.args[a];
    if (instr.kind == IrOpKind::constant) {
      text << " [";
      for (int c = 0; c < instr.data_count; ++c) text << (c ? ", " : "") << ir.data[instr.data_offset + c];
      text << "]";
    }
    if (instr.kind == IrOpKind::param) text << " @" << instr.immediate[0];
    if (instr.uniform && instr.kind == IrOpKind::op) text << "  uniform";
    if (!instr.source.empty()) text << "  ; " << instr.source;
    text << "\n";
    if (instr.kind == IrOpKind::begin_region) ++depth;
  }
  for (const IrOutput& output : ir.outputs)
    text << "output " << output.name << ": " << type_name(output.type) << " = %" << output.value << "\n";
  return text.str();
}

}  // namespace shadetree

#include "ir/kernel.h"

namespace shadetree {

KernelInputs KernelInputs::advanced(std::size_t offset) const {
  KernelInputs result = *this;
  auto shift = [offset](const float*& plane) {
    if (plane) plane += offset;
  };
  for (auto& plane : result.P) shift(plane);
  for (auto& plane : result.N) shift(plane);
  for (auto& plane : result.uv) shift(plane);
  shift(result.filter_width);
  shift(result.density);
  return result;
}

void KernelInputs::planes(const float* out[input_plane_count]) const {
  const float* all[input_plane_count] = {P[0], P[1], P[2], N[0], N[1], N[2], uv[0], uv[1], filter_width, density};
  std::copy(all, all + input_plane_count, out);
}

KernelInputs InputBuffers::inputs(float time, float frame) const {
  KernelInputs in;
  for (int c = 0; c < 3; ++c) {
    in.P[c] = plane(static_cast<InputPlane>(static_cast<int>(InputPlane::P_x) + c));
    in.N[c] = plane(static_cast<InputPlane>(static_cast<int>(InputPlane::N_x) + c));
  }
  in.uv[0] = plane(InputPlane::u);
  in.uv[1] = plane(InputPlane::v);
  in.filter_width = plane(InputPlane::filter_width);
  in.density = plane(InputPlane::density);
  in.time = time;
  in.frame = frame;
  return in;
}

InputUsage input_usage(const ShadeIR& ir) {
  InputUsage usage;
  for (const IrInstr& instr : ir.code) {
    if (instr.kind != IrOpKind::op) continue;
    usage.P |= instr.op == OpId::P;
    usage.N |= instr.op == OpId::N;
    usage.uv |= instr.op == OpId::uv;
    usage.filter_width |= instr.op == OpId::filter_width;
    usage.density |= instr.op == OpId::density;
  }
  return usage;
}

}  // namespace shadetree
