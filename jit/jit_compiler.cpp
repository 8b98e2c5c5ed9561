#include "jit/jit_compiler.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include <llvm/ExecutionEngine/ObjectCache.h>
#include <llvm/ExecutionEngine/Orc/CompileUtils.h>
#include <llvm/ExecutionEngine/Orc/ExecutionUtils.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/IR/Module.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/ErrorHandling.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/xxhash.h>
#include <llvm/Target/TargetMachine.h>
#include <llvm/TargetParser/Host.h>

#include "codegen/op_library.h"
#include "nodes/noise_tables.h"

namespace shadetree {
namespace {

bool host_has(const char* feature) {
  static const auto features = llvm::sys::getHostCPUFeatures();
  auto found = features.find(feature);
  return found != features.end() && found->second;
}

// In-register lookups use AVX-512 instructions: never emit them on a host
// without it, whatever the settings ask for.
GatherStrategy effective_gathers(const JitSettings& settings) {
  const GatherStrategy wanted = settings.gathers.value_or(host_gather_strategy());
  const bool needs_avx512 =
      wanted == GatherStrategy::in_register || wanted == GatherStrategy::in_register_byte_permutes;
  if (needs_avx512 && host_vector_width() < 16) return GatherStrategy::per_lane;
  if (wanted == GatherStrategy::in_register_byte_permutes && !host_has("avx512vbmi")) return GatherStrategy::in_register;
  return wanted;
}

// What a cached object's calling convention depends on: the op table, the
// globals table and the output contracts (ir/kernel.h), hashed once.
std::uint64_t kernel_abi_hash() {
  static const std::uint64_t hash = llvm::xxh3_64bits(llvm::StringRef(kernel_abi()));
  return hash;
}

constexpr unsigned max_instructions_for_full_codegen = 6000;

std::string error_text(llvm::Error error) {
  std::string text;
  llvm::handleAllErrors(std::move(error), [&](const llvm::ErrorInfoBase& info) { text += info.message(); });
  return text;
}

std::string host_features() {
  llvm::SubtargetFeatures features;
  for (const auto& [name, enabled] : llvm::sys::getHostCPUFeatures()) features.AddFeature(name, enabled);
  return features.getString();
}

// A canonical text of everything the machine code depends on.
std::string canonical_key(const ShadeIR& ir, int width, GatherStrategy gathers) {
  std::ostringstream text;
  text << kernel_abi_hash() << " " << op_library_hash() << " " << SHADETREE_CODEGEN_DIGEST << "\n" << width << " " << static_cast<int>(gathers) << "\n" << llvm::sys::getHostCPUName().str() << "\n" << host_features() << "\n";
  for (const IrInstr& instr : ir.code) {
    text << static_cast<int>(instr.kind) << ' ' << static_cast<int>(instr.op) << ' ' << static_cast<int>(instr.type)
         << ' ' << static_cast<int>(instr.generic)
         << ' ' << instr.uniform << ' ' << instr.data_offset << ' ' << instr.data_count << ' ' << instr.immediate[0]
         << ' ' << instr.immediate[1];
    for (int a = 0; a < instr.arg_count; ++a) text << ' ' << instr.args[a];
    text << '\n';
  }
  text.write(reinterpret_cast<const char*>(ir.data.data()), static_cast<std::streamsize>(ir.data.size() * sizeof(float)));
  text << "kind " << static_cast<int>(ir.kind) << '\n';
  for (const IrOutput& output : ir.outputs)
    text << "out " << static_cast<int>(output.id) << ' ' << output.value << ' ' << static_cast<int>(output.type) << '\n';
  return text.str();
}

std::string kernel_name(const std::string& key) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(llvm::xxh3_64bits(llvm::StringRef(key))));
  return std::string("shade_kernel_") + hex;
}

std::filesystem::path cache_folder(const JitSettings& settings) {
  if (!settings.cache_folder.empty()) return settings.cache_folder;
  if (const char* folder = std::getenv("SHADETREE_CACHE_DIR"); folder && *folder) return folder;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "shadetree";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "shadetree";
  return {};
}

// Writes each compiled object next to its kernel name; reading is done by
// the compiler below before any IR is built.
class DiskObjectCache final : public llvm::ObjectCache {
 public:
  void notifyObjectCompiled(const llvm::Module* module, llvm::MemoryBufferRef object) override {
    // Only kernels: LLJIT compiles modules of its own too (__standard_lib).
    if (folder_.empty() || !module->getModuleIdentifier().starts_with("shade_kernel_")) return;
    std::error_code error;
    std::filesystem::create_directories(folder_, error);
    const auto target = folder_ / (module->getModuleIdentifier() + ".o");
    const auto temporary =
        folder_ / (module->getModuleIdentifier() + ".o.partial-" + std::to_string(static_cast<long>(::getpid())));
    std::ofstream file(temporary, std::ios::binary);
    file.write(object.getBufferStart(), static_cast<std::streamsize>(object.getBufferSize()));
    file.close();
    if (!file) {  // a cache that cannot be written is only a missed speed-up
      std::filesystem::remove(temporary, error);
      return;
    }
    std::filesystem::rename(temporary, target, error);
    if (error) std::filesystem::remove(temporary, error);
  }
  std::unique_ptr<llvm::MemoryBuffer> getObject(const llvm::Module*) override { return nullptr; }
  void set_folder(std::filesystem::path folder) { folder_ = std::move(folder); }

 private:
  std::filesystem::path folder_;
};

class Jit {
 public:
  static Jit& instance() {
    static Jit jit;
    return jit;
  }

  Result<CompiledKernel> compile(const ShadeIR& ir, int width, const JitSettings& settings) {
    if (!jit_) return failure("cannot start the LLVM JIT (--backend interp still works): " + startup_error_);
    if (width == 0) width = host_vector_width();
    const auto start = std::chrono::steady_clock::now();
    const GatherStrategy gathers = effective_gathers(settings);
    std::string name = kernel_name(canonical_key(ir, width, gathers));
    std::lock_guard lock(mutex_);
    auto elapsed = [&] {
      return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    if (settings.cold) {
      name += "_cold" + std::to_string(++cold_compiles_);
      object_cache_->set_folder({});
      return build_and_add(ir, width, name, gathers, elapsed);
    }
    if (auto found = kernels_.find(name); found != kernels_.end()) {
      CompiledKernel kernel = found->second;
      kernel.cache = CacheHit::memory;
      kernel.compile_milliseconds = elapsed();
      return kernel;
    }
    const std::filesystem::path folder = settings.disk_cache ? cache_folder(settings) : std::filesystem::path();
    object_cache_->set_folder(folder);
    if (!folder.empty()) {
      auto object = llvm::MemoryBuffer::getFile((folder / (name + ".o")).string());
      if (object) {
        if (llvm::Error error = jit_->addObjectFile(std::move(*object))) {
          llvm::consumeError(std::move(error));
        } else if (Result<CompiledKernel> found = look_up(name, width)) {
          found->compile_milliseconds = elapsed();
          found->cache = CacheHit::disk;
          return remember(name, *found);
        }
      }
    }
    Result<CompiledKernel> compiled = build_and_add(ir, width, name, gathers, elapsed);
    if (!compiled) return compiled;
    return remember(name, *compiled);
  }

  Result<std::unique_ptr<llvm::Module>> build_optimized_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                               const std::string& name, GatherStrategy gathers) {
    if (!target_machine_) return failure("cannot start the LLVM JIT: " + startup_error_);
    Result<std::unique_ptr<llvm::Module>> module = emit_kernel_module(ir, width, context, name, gathers);
    if (!module) return module.error();
    llvm::Module& m = **module;
    m.setDataLayout(target_machine_->createDataLayout());
    m.setTargetTriple(target_machine_->getTargetTriple().str());
    for (llvm::Function& function : m) {
      if (function.isDeclaration()) continue;
      function.addFnAttr("target-cpu", target_machine_->getTargetCPU());
      function.addFnAttr("target-features", target_machine_->getTargetFeatureString());
    }
    optimize_module(m);
    return module;
  }

  std::mutex& mutex() { return mutex_; }

  Result<std::string> assembly(llvm::Module& module) {
    llvm::SmallString<0> text;
    llvm::raw_svector_ostream stream(text);
    llvm::legacy::PassManager passes;
    if (target_machine_->addPassesToEmitFile(passes, stream, nullptr, llvm::CodeGenFileType::AssemblyFile))
      return failure("LLVM cannot emit assembly for this target");
    passes.run(module);
    return std::string(text.str());
  }

 private:
  Jit() {
    // LLVM reports some failures (instruction selection, a broken object
    // file) by aborting; make them the one-line error and status 1 that
    // every other failure of shadetree gets.
    llvm::install_fatal_error_handler([](void*, const char* reason, bool) {
      std::fprintf(stderr, "error: LLVM: %s\n", reason);
      std::_Exit(static_cast<int>(ExitStatus::failure));
    });
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
    llvm::InitializeNativeTargetAsmParser();
    auto machine_builder = llvm::orc::JITTargetMachineBuilder::detectHost();
    if (!machine_builder) {
      startup_error_ = error_text(machine_builder.takeError());
      return;
    }
    machine_builder->setCPU(llvm::sys::getHostCPUName().str());
    machine_builder->getFeatures().addFeaturesVector(
        llvm::SubtargetFeatures(host_features()).getFeatures());
    machine_builder->setCodeGenOptLevel(llvm::CodeGenOptLevel::Aggressive);
    auto target_machine = machine_builder->createTargetMachine();
    if (!target_machine) {
      startup_error_ = error_text(target_machine.takeError());
      return;
    }
    target_machine_ = std::move(*target_machine);
    llvm::orc::JITTargetMachineBuilder fast_builder = *machine_builder;
    fast_builder.setCodeGenOptLevel(llvm::CodeGenOptLevel::None);
    auto fast_target_machine = fast_builder.createTargetMachine();
    if (!fast_target_machine) {
      startup_error_ = error_text(fast_target_machine.takeError());
      return;
    }
    fast_target_machine_ = std::move(*fast_target_machine);
    object_cache_ = std::make_unique<DiskObjectCache>();
    auto jit = llvm::orc::LLJITBuilder()
                   .setJITTargetMachineBuilder(*machine_builder)
                   .setCompileFunctionCreator([this](llvm::orc::JITTargetMachineBuilder builder)
                                                  -> llvm::Expected<std::unique_ptr<llvm::orc::IRCompileLayer::IRCompiler>> {
                     auto machine = builder.createTargetMachine();
                     if (!machine) return machine.takeError();
                     return std::make_unique<llvm::orc::TMOwningSimpleCompiler>(std::move(*machine),
                                                                                object_cache_.get());
                   })
                   .create();
    if (!jit) {
      startup_error_ = error_text(jit.takeError());
      return;
    }
    jit_ = std::move(*jit);
    // Generated code may call C runtime helpers (memcpy, memset) that LLVM
    // introduces; resolve them from the process.
    auto process = llvm::orc::DynamicLibrarySearchGenerator::GetForCurrentProcess(
        jit_->getDataLayout().getGlobalPrefix());
    if (!process) {
      startup_error_ = error_text(process.takeError());
      jit_.reset();
      return;
    }
    jit_->getMainJITDylib().addGenerator(std::move(*process));
  }

  template <class Elapsed>
  Result<CompiledKernel> build_and_add(const ShadeIR& ir, int width, const std::string& name, GatherStrategy gathers,
                                       Elapsed elapsed) {
    auto context = std::make_unique<llvm::LLVMContext>();
    Result<std::unique_ptr<llvm::Module>> module = build_optimized_module(ir, width, *context, name, gathers);
    if (!module) return module.error();
    // Instruction selection, scheduling and greedy register allocation grow
    // faster than the kernel: a 4000-instruction graph spent 2 s there. A
    // kernel this large is compiled with the fast, linear path instead
    // (slower code, a compile in a fraction of the time).
    if ((*module)->getInstructionCount() > max_instructions_for_full_codegen) {
      auto object = llvm::orc::SimpleCompiler(*fast_target_machine_)(**module);
      if (!object) return failure("JIT: " + error_text(object.takeError()));
      object_cache_->notifyObjectCompiled(module->get(), (*object)->getMemBufferRef());
      if (llvm::Error error = jit_->addObjectFile(std::move(*object)))
        return failure("JIT: " + error_text(std::move(error)));
    } else if (llvm::Error error =
                   jit_->addIRModule(llvm::orc::ThreadSafeModule(std::move(*module), std::move(context)))) {
      return failure("JIT: " + error_text(std::move(error)));
    }
    Result<CompiledKernel> compiled = look_up(name, width);
    if (compiled) compiled->compile_milliseconds = elapsed();
    return compiled;
  }

  // The kernel's two functions, once its module or object is in the JIT.
  Result<CompiledKernel> look_up(const std::string& name, int width) {
    auto bind = jit_->lookup(name + "_bind");
    if (!bind) return failure("JIT: " + error_text(bind.takeError()));
    auto run = jit_->lookup(name + "_run");
    if (!run) return failure("JIT: " + error_text(run.takeError()));
    return CompiledKernel{bind->toPtr<KernelBindFunction>(), run->toPtr<KernelRunFunction>(), width, 0, CacheHit::none};
  }

  void optimize_module(llvm::Module& module) {
    llvm::LoopAnalysisManager loops;
    llvm::FunctionAnalysisManager functions;
    llvm::CGSCCAnalysisManager cgscc;
    llvm::ModuleAnalysisManager modules;
    llvm::PassBuilder builder(target_machine_.get());
    builder.registerModuleAnalyses(modules);
    builder.registerCGSCCAnalyses(cgscc);
    builder.registerFunctionAnalyses(functions);
    builder.registerLoopAnalyses(loops);
    builder.crossRegisterProxies(loops, functions, cgscc, modules);
    builder.buildPerModuleDefaultPipeline(llvm::OptimizationLevel::O3).run(module, modules);
  }

  Result<CompiledKernel> remember(const std::string& name, CompiledKernel kernel) {
    kernels_[name] = kernel;
    return kernel;
  }

  std::string startup_error_;
  std::unique_ptr<llvm::TargetMachine> target_machine_;
  std::unique_ptr<llvm::TargetMachine> fast_target_machine_;  // for huge kernels: see build_and_add
  std::unique_ptr<DiskObjectCache> object_cache_;
  std::unique_ptr<llvm::orc::LLJIT> jit_;
  std::mutex mutex_;
  std::map<std::string, CompiledKernel> kernels_;
  int cold_compiles_ = 0;
};

}  // namespace

int host_vector_width() {
  if (host_has("avx512f")) return 16;
  if (host_has("avx2")) return 8;
  return 4;
}

Result<CompiledKernel> compile_kernel(const ShadeIR& ir, int width, const JitSettings& settings) {
  return Jit::instance().compile(ir, width, settings);
}

// Measured with `shadetree bench --gathers` (figures in docs/architecture.md):
// per-lane loads beat vgatherdps on the x86 parts we have, permutes over
// registers beat both where AVX-512 allows them, and byte permutes (VBMI)
// do the noise permutation cheaper still.
GatherStrategy host_gather_strategy() {
  if (host_vector_width() < 16) return GatherStrategy::per_lane;
  return host_has("avx512vbmi") ? GatherStrategy::in_register_byte_permutes : GatherStrategy::in_register;
}

Result<std::string> kernel_listing(const ShadeIR& ir, int width, Listing listing, const JitSettings& settings) {
  if (width == 0) width = host_vector_width();
  std::lock_guard lock(Jit::instance().mutex());  // the target machine is shared with compile()
  llvm::LLVMContext context;
  Result<std::unique_ptr<llvm::Module>> module = Jit::instance().build_optimized_module(
      ir, width, context, "shade_kernel", effective_gathers(settings));
  if (!module) return module.error();
  if (listing == Listing::assembly) return Jit::instance().assembly(**module);
  std::string text;
  llvm::raw_string_ostream stream(text);
  (*module)->print(stream, nullptr);
  return text;
}

}  // namespace shadetree
