// The constants each op call of a module passes (OpConstants, nodes/
// op_frame.h) as constant LLVM globals of the same layout, so that their
// loads fold away once the op is inlined: the graph's data, the noise
// tables of each seed, and per instruction its immediates and component
// counts. Shared by the kernel emitter and the interval program emitter.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "ir/shade_ir.h"

namespace llvm {
class Constant;
class GlobalVariable;
class Module;
class StructType;
}  // namespace llvm

namespace shadetree {

class OpConstantGlobals {
 public:
  // Graph data past max_embedded_data_bytes (codegen/emit_kernel.h) is
  // declared as `data_symbol` for whoever links the module to bind.
  OpConstantGlobals(const ShadeIR& ir, llvm::Module& module, const std::string& data_symbol);

  // The OpConstants of op instruction `instr`, as a constant global.
  llvm::Constant* of(const IrInstr& instr);

 private:
  llvm::Constant* data_pointer(const IrInstr& instr);
  llvm::Constant* noise_tables(std::uint32_t seed);

  llvm::Module& module_;
  llvm::StructType* type_ = nullptr;
  llvm::GlobalVariable* data_ = nullptr;
  std::map<std::uint32_t, llvm::Constant*> tables_;
};

}  // namespace shadetree
