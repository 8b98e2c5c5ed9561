#include "ir/differentiate.h"

namespace shadetree {
namespace {

bool made_of_floats(Type type) { return type != Type::int_ && type != Type::bool_; }

bool is_p(const IrInstr& instr) {
  return instr.kind == IrOpKind::global && instr.immediate[0] == static_cast<std::int32_t>(GlobalId::P);
}

}  // namespace

std::int32_t Differentiator::append(IrInstr instr) {
  ir_.code.push_back(std::move(instr));
  twin_.push_back(-1);
  return static_cast<std::int32_t>(ir_.code.size() - 1);
}

std::int32_t Differentiator::gradient(std::int32_t value, const std::string& source) {
  twin_.resize(ir_.code.size(), -1);
  // The cone of `value`: everything it is computed from.
  std::vector<bool> in_cone(static_cast<std::size_t>(value) + 1, false);
  in_cone[value] = true;
  for (std::int32_t i = value; i >= 0; --i) {
    if (!in_cone[i]) continue;
    const IrInstr& instr = ir_.code[i];
    for (int a = 0; a < instr.arg_count; ++a) in_cone[instr.args[a]] = true;
  }
  // Twins in program order, so that each one's arguments come first.
  for (std::int32_t i = 0; i <= value; ++i) {
    if (!in_cone[i] || twin_[i] >= 0) continue;
    const IrInstr& instr = ir_.code[i];
    if (!made_of_floats(instr.type) || instr.uniform) continue;
    bool reads_dual = false;
    for (int a = 0; a < instr.arg_count; ++a) reads_dual = reads_dual || twin_[instr.args[a]] >= 0;
    const bool computed = (instr.kind == IrOpKind::op || instr.kind == IrOpKind::extract) && reads_dual;
    if (!computed && !is_p(instr)) continue;
    IrInstr twin = instr;
    twin.dual = true;
    for (int a = 0; a < twin.arg_count; ++a)
      if (twin_[twin.args[a]] >= 0) twin.args[a] = twin_[twin.args[a]];
    twin_[i] = append(std::move(twin));
  }
  IrInstr result;
  result.type = Type::vec3;
  result.source = source;
  if (twin_[value] < 0) {
    result.kind = IrOpKind::constant;
    result.uniform = true;
    result.data_offset = static_cast<std::int32_t>(ir_.data.size());
    result.data_count = 1;
    ir_.data.push_back(0.0f);
    return append(std::move(result));
  }
  result.kind = IrOpKind::partials;
  result.arg_count = 1;
  result.args[0] = twin_[value];
  return append(std::move(result));
}

}  // namespace shadetree
