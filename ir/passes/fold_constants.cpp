// Constant folding. An op whose arguments are all constants computes the
// same value for every sample of every call, so it is computed once, here,
// and becomes a constant. The value comes from running a two-instruction
// program through the given evaluator (the reference interpreter), so
// folding cannot change what a graph computes. Folding in program order
// folds whole constant chains, since each folded op is a constant for its
// users. Params and uniform globals (time, frame...) are uniform but not
// constant: backends compute what depends on them once per binding instead.
#include "ir/passes/fold_constants.h"

namespace shadetree {
namespace {

bool foldable(const ShadeIR& ir, const IrInstr& instr) {
  if (instr.kind == IrOpKind::extract) return ir.code[instr.args[0]].kind == IrOpKind::constant;
  if (instr.kind != IrOpKind::op) return false;
  for (int a = 0; a < instr.arg_count; ++a)
    if (ir.code[instr.args[a]].kind != IrOpKind::constant) return false;
  return true;
}

}  // namespace

void fold_constants(ShadeIR& ir, const ConstantEvaluator& evaluate) {
  for (IrInstr& instr : ir.code) {
    if (!foldable(ir, instr)) continue;
    ShadeIR program;
    for (int a = 0; a < instr.arg_count; ++a) {
      IrInstr argument = ir.code[instr.args[a]];
      argument.data_offset = static_cast<std::int32_t>(program.data.size());
      program.data.insert(program.data.end(), ir.data.begin() + ir.code[instr.args[a]].data_offset,
                          ir.data.begin() + ir.code[instr.args[a]].data_offset + argument.data_count);
      program.code.push_back(argument);
    }
    IrInstr folded = instr;
    for (int a = 0; a < instr.arg_count; ++a) folded.args[a] = a;
    folded.data_offset = static_cast<std::int32_t>(program.data.size());
    program.data.insert(program.data.end(), ir.data.begin() + instr.data_offset,
                        ir.data.begin() + instr.data_offset + instr.data_count);
    program.code.push_back(folded);
    const std::vector<float> value = evaluate(program);

    IrInstr constant;
    constant.kind = IrOpKind::constant;
    constant.type = instr.type;
    constant.uniform = true;
    constant.data_offset = static_cast<std::int32_t>(ir.data.size());
    constant.data_count = static_cast<std::int32_t>(value.size());
    constant.source = instr.source;
    ir.data.insert(ir.data.end(), value.begin(), value.end());
    instr = constant;
  }
}

}  // namespace shadetree
