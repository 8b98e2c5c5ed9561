#include "ir/interval_lengths_read.h"

namespace shadetree {

std::vector<char> interval_lengths_read(const ShadeIR& ir) {
  std::vector<char> read(ir.code.size(), 0);
  // Users come after their arguments, so each is decided before them.
  for (std::size_t i = ir.code.size(); i-- > 0;) {
    const IrInstr& instr = ir.code[i];
    if (instr.kind != IrOpKind::op) continue;
    const bool reads = instr.op == OpId::length || instr.op == OpId::dot || instr.op == OpId::sphere ||
                       (read[i] && (instr.op == OpId::neg || instr.op == OpId::mul || instr.op == OpId::add ||
                                    instr.op == OpId::sub));
    if (!reads) continue;
    for (int a = 0; a < instr.arg_count; ++a) {
      const IrInstr& argument = ir.code[static_cast<std::size_t>(instr.args[a])];
      // A scalar read as a vector has no length of its own to keep.
      const int held = component_count(argument.type);
      if (held >= 2 && held == component_count(argument_type(instr, a))) read[static_cast<std::size_t>(instr.args[a])] = 1;
    }
  }
  return read;
}

}  // namespace shadetree
