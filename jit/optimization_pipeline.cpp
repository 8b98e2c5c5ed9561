#include "jit/optimization_pipeline.h"

#include <llvm/ADT/SmallString.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/IR/Module.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>

namespace shadetree {

llvm::CodeGenOptLevel code_generation_level(Optimization optimization) {
  return optimization == Optimization::full ? llvm::CodeGenOptLevel::Aggressive : llvm::CodeGenOptLevel::None;
}

namespace {

// The quick pipeline: the library inlined (it was optimized when it was
// built), then only what makes the inlined code straight again.
constexpr const char* quick_pipeline = "always-inline,globaldce,function(sroa,early-cse,simplifycfg,adce)";

void optimize_module(llvm::Module& module, llvm::TargetMachine& machine, Optimization optimization) {
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
  if (optimization == Optimization::full) {
    builder.buildPerModuleDefaultPipeline(llvm::OptimizationLevel::O3).run(module, modules);
    return;
  }
  llvm::ModulePassManager passes;
  llvm::cantFail(builder.parsePassPipeline(passes, quick_pipeline));
  passes.run(module, modules);
}

}  // namespace

Result<std::unique_ptr<llvm::Module>> build_optimized_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                             const std::string& name, GatherStrategy gathers,
                                                             llvm::TargetMachine& machine, Optimization optimization) {
  Result<std::unique_ptr<llvm::Module>> module = emit_kernel_module(ir, width, context, name, gathers);
  if (!module) return module.error();
  llvm::Module& m = **module;
  m.setDataLayout(machine.createDataLayout());
  m.setTargetTriple(machine.getTargetTriple().str());
  for (llvm::Function& function : m) {
    if (function.isDeclaration()) continue;
    function.addFnAttr("target-cpu", machine.getTargetCPU());
    function.addFnAttr("target-features", machine.getTargetFeatureString());
  }
  optimize_module(m, machine, optimization);
  return module;
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
