#include "jit/optimization_pipeline.h"

#include <chrono>

#include <llvm/ADT/SmallString.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/IR/Module.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>

#include "jit/lane_index_chains.h"
#include "jit/library_inliner.h"

namespace shadetree {

llvm::CodeGenOptLevel code_generation_level(Optimization optimization) {
  return optimization == Optimization::full ? llvm::CodeGenOptLevel::Aggressive : llvm::CodeGenOptLevel::None;
}

namespace {

// Both pipelines run on the kernel with the op library inlined
// (jit/library_inliner.h).
//
// The quick pipeline: only what makes the inlined code straight again
// (the library was optimized when it was built).
constexpr const char* quick_pipeline = "globaldce,function(sroa,early-cse,simplifycfg,adce)";

// The full pipeline: what O3 does that changes a kernel, in half of O3's
// time (O3's second inliner, loop unrolling and vectorizers find little in
// a body of vector code whose library was optimized when it was built).
// Constants into outlined ops (IPSCCP) and their pointer
// arguments made values (argument promotion), before the function passes
// fold what that exposes in the kernel; then arguments passed through
// memory made registers (SROA), repeated and constant work removed
// (early CSE, InstCombine, GVN), uniform work lifted out of the sample and
// octave loops (LICM: only what every iteration runs; hoisting what a
// conditional region computes was most of its time and changed 3 of the
// gallery's 48 kernels), and dead code and constants dropped. Its kernels
// match O3's instruction for instruction within 2% on the gallery, with as
// many memory reads in their loops (see docs/architecture.md). GVN numbers
// values only: early CSE over MemorySSA has already removed the repeated
// loads, and GVN's own load elimination (memory dependence, an alias query
// per load against the hundreds of table reads before it) found nothing
// more on any gallery kernel while costing a third of the middle end.
constexpr const char* full_pipeline =
    "ipsccp,globalopt,cgscc(function-attrs,argpromotion),"
    "function(sroa,early-cse<memssa>,instcombine<no-verify-fixpoint;max-iterations=1>,simplifycfg,"
    "loop-mssa(licm<no-allowspeculation>),gvn<no-memdep>,adce,simplifycfg),"
    "deadargelim,constmerge,globaldce";

void optimize_module(llvm::Module& module, llvm::TargetMachine& machine, Optimization optimization) {
  inline_library_calls(module);
  llvm::LoopAnalysisManager loops;
  llvm::FunctionAnalysisManager functions;
  llvm::CGSCCAnalysisManager cgscc;
  llvm::ModuleAnalysisManager modules;
  llvm::PassBuilder builder(&machine);
  builder.registerModuleAnalyses(modules);
  builder.registerCGSCCAnalyses(cgscc);
  builder.registerFunctionAnalyses(functions);
  builder.registerLoopAnalyses(loops);
  builder.crossRegisterProxies(loops, functions, cgscc, modules);
  llvm::ModulePassManager passes;
  llvm::cantFail(builder.parsePassPipeline(passes, optimization == Optimization::full ? full_pipeline : quick_pipeline));
  passes.run(module, modules);
}

}  // namespace

Result<std::unique_ptr<llvm::Module>> build_optimized_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                             const std::string& name, GatherStrategy gathers,
                                                             llvm::TargetMachine& machine, Optimization optimization,
                                                             KernelPart part, const KernelSplit& split,
                                                             CompileStages* stages) {
  const auto start = std::chrono::steady_clock::now();
  Result<std::unique_ptr<llvm::Module>> module = emit_kernel_module(ir, width, context, name, gathers, part, split);
  if (!module) return module.error();
  const auto emitted = std::chrono::steady_clock::now();
  optimize_for(**module, machine, optimization);
  if (stages) {
    stages->emit_milliseconds += std::chrono::duration<double, std::milli>(emitted - start).count();
    stages->optimize_milliseconds +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - emitted).count();
  }
  return module;
}

void optimize_for(llvm::Module& module, llvm::TargetMachine& machine, Optimization optimization) {
  module.setDataLayout(machine.createDataLayout());
  module.setTargetTriple(machine.getTargetTriple().str());
  for (llvm::Function& function : module) {
    if (function.isDeclaration()) continue;
    function.addFnAttr("target-cpu", machine.getTargetCPU());
    function.addFnAttr("target-features", machine.getTargetFeatureString());
  }
  optimize_module(module, machine, optimization);
  // Last: InstCombine moves a lane out of a vector operation only where
  // nothing else reads the operation, so these chains are still vectors.
  for (llvm::Function& function : module)
    if (!function.isDeclaration()) index_lanes_in_general_registers(function);
}

Result<std::string> assembly(llvm::Module& module, llvm::TargetMachine& machine) {
  llvm::SmallString<0> text;
  llvm::raw_svector_ostream stream(text);
  llvm::legacy::PassManager passes;
  if (machine.addPassesToEmitFile(passes, stream, nullptr, llvm::CodeGenFileType::AssemblyFile))
    return failure("LLVM cannot emit assembly for this target");
  passes.run(module);
  return std::string(text.str());
}

}  // namespace shadetree
