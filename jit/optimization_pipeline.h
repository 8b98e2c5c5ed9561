// What a kernel module goes through between the code generator's LLVM IR
// and machine code, by JitSettings::optimization: the full pipeline (O3's
// effect on a kernel in half its time) and LLVM's optimizing code
// generator, or the quick one (the library inlined and cleaned up, the
// fast code generator); after either, chained per-lane lookups are
// indexed in general registers (jit/lane_index_chains.h).
#pragma once

#include <memory>
#include <string>

#include <llvm/Support/CodeGen.h>

#include "codegen/emit_kernel.h"
#include "graph/diagnostic.h"
#include "jit/jit_compiler.h"

namespace llvm {
class TargetMachine;
}

namespace shadetree {

llvm::CodeGenOptLevel code_generation_level(Optimization optimization);

// The kernel module of `ir` (or of a part of it: emit_kernel_module),
// made for `machine` and optimized; the time each took is added to
// `stages` where given.
Result<std::unique_ptr<llvm::Module>> build_optimized_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                             const std::string& name, GatherStrategy gathers,
                                                             llvm::TargetMachine& machine, Optimization optimization,
                                                             KernelPart part = KernelPart::whole,
                                                             const KernelSplit& split = {},
                                                             CompileStages* stages = nullptr);

// An emitted module (a kernel's, an interval program's) made for
// `machine` and optimized.
void optimize_for(llvm::Module& module, llvm::TargetMachine& machine, Optimization optimization);

// The module's assembly for `machine`.
Result<std::string> assembly(llvm::Module& module, llvm::TargetMachine& machine);

}  // namespace shadetree
