#include "ir/output_dependencies.h"

#include <algorithm>

namespace shadetree {

OutputDependencies output_dependencies(const ShadeIR& ir, const std::vector<OutputId>& outputs) {
  OutputDependencies needs;
  needs.instructions.assign(ir.code.size(), 0);
  needs.outputs.assign(ir.outputs.size(), 0);
  for (std::size_t o = 0; o < ir.outputs.size(); ++o)
    if (outputs.empty() || std::find(outputs.begin(), outputs.end(), ir.outputs[o].id) != outputs.end()) {
      needs.outputs[o] = 1;
      needs.instructions[static_cast<std::size_t>(ir.outputs[o].value)] = 1;
    }
  // A region's contents come after its marker, so are decided first.
  for (std::size_t i = ir.code.size(); i-- > 0;) {
    const IrInstr& instr = ir.code[i];
    if (instr.kind == IrOpKind::begin_region) {
      const auto end = static_cast<std::size_t>(instr.immediate[1]);
      if (std::any_of(needs.instructions.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                      needs.instructions.begin() + static_cast<std::ptrdiff_t>(end), [](char n) { return n != 0; }))
        needs.instructions[i] = needs.instructions[end] = 1;
    }
    if (!needs.instructions[i]) continue;
    for (int a = 0; a < instr.arg_count; ++a) needs.instructions[static_cast<std::size_t>(instr.args[a])] = 1;
  }
  return needs;
}

}  // namespace shadetree
