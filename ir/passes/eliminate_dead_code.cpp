// Dead code elimination: a node nothing reads costs every sample, so it is
// dropped before any backend sees it. One backward sweep suffices because
// arguments always precede their users.
#include "ir/passes/eliminate_dead_code.h"

namespace shadetree {

void eliminate_dead_code(ShadeIR& ir) {
  std::vector<bool> live(ir.code.size(), false);
  for (const IrOutput& output : ir.outputs) live[output.value] = true;
  for (std::size_t i = ir.code.size(); i-- > 0;) {
    if (!live[i]) continue;
    const IrInstr& instr = ir.code[i];
    for (int a = 0; a < instr.arg_count; ++a) live[instr.args[a]] = true;
  }
  std::vector<std::int32_t> order;
  for (std::size_t i = 0; i < ir.code.size(); ++i)
    if (live[i]) order.push_back(static_cast<std::int32_t>(i));
  reorder_shade_ir(ir, order);
}

}  // namespace shadetree
