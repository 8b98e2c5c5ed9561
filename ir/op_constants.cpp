#include "ir/op_constants.h"

#include "nodes/registry.h"

namespace shadetree {

OpConstants op_constants(const ShadeIR& ir, const IrInstr& instr) {
  OpConstants constants;
  constants.data = ir.data.data() + instr.data_offset;
  constants.data_count = instr.data_count;
  constants.immediate[0] = instr.immediate[0];
  constants.immediate[1] = instr.immediate[1];
  constants.components = component_count(instr.type);
  for (int a = 0; a < instr.arg_count; ++a) constants.arg_components[a] = component_count(argument_type(instr, a));
  if (op_def(instr.op).tables == OpTables::noise)
    constants.tables = &noise_tables(static_cast<std::uint32_t>(instr.immediate[0]));
  return constants;
}

}  // namespace shadetree
