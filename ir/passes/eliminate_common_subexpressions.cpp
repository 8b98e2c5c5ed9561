// Common subexpression elimination. Graphs repeat work, most often through
// functions inlined several times (marble_color applied twice, the same
// noise octave in two branches) and through literals written more than
// once. Ops are pure, so two instructions with the same op, type, dual
// form, arguments, immediates and constant data compute the same value; later
// ones are redirected to the first, and dead code elimination then drops
// them. Arguments are renumbered before each instruction is keyed, so
// chains of duplicates collapse in one forward sweep.
#include "ir/passes/eliminate_common_subexpressions.h"

#include <cstring>
#include <map>
#include <string>

namespace shadetree {
namespace {

std::string key_of(const ShadeIR& ir, const IrInstr& instr) {
  std::string key;
  auto append = [&key](const void* bytes, std::size_t size) { key.append(static_cast<const char*>(bytes), size); };
  append(&instr.kind, sizeof instr.kind);
  append(&instr.op, sizeof instr.op);
  append(&instr.type, sizeof instr.type);
  append(&instr.generic, sizeof instr.generic);
  append(&instr.dual, sizeof instr.dual);
  append(&instr.arg_count, sizeof instr.arg_count);
  append(instr.args.data(), sizeof(std::int32_t) * instr.arg_count);
  append(instr.immediate.data(), sizeof instr.immediate);
  append(ir.data.data() + instr.data_offset, sizeof(float) * static_cast<std::size_t>(instr.data_count));
  return key;
}

}  // namespace

void eliminate_common_subexpressions(ShadeIR& ir) {
  std::vector<std::int32_t> replacement(ir.code.size());
  std::map<std::string, std::int32_t> first;
  for (std::size_t i = 0; i < ir.code.size(); ++i) {
    IrInstr& instr = ir.code[i];
    for (int a = 0; a < instr.arg_count; ++a) instr.args[a] = replacement[instr.args[a]];
    replacement[i] = static_cast<std::int32_t>(i);
    if (instr.kind == IrOpKind::begin_region || instr.kind == IrOpKind::end_region) continue;
    auto [found, inserted] = first.emplace(key_of(ir, instr), static_cast<std::int32_t>(i));
    if (!inserted) replacement[i] = found->second;
  }
  for (IrOutput& output : ir.outputs) output.value = replacement[output.value];
}

}  // namespace shadetree
