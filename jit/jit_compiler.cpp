#include "jit/jit_compiler.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

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
std::atomic<long> resident_kernels{0};
}  // namespace

struct KernelCode {
  KernelCode(std::string name, llvm::orc::ResourceTrackerSP tracker, const CompiledKernel& functions,
             std::recursive_mutex& jit_mutex)
      : name(std::move(name)), tracker(std::move(tracker)), bind(functions.bind), run(functions.run),
        width(functions.width), jit_mutex(jit_mutex) {
    ++resident_kernels;
  }
  // Removes the code under the JIT's lock, so a compile of the same
  // program waits until these symbols are gone before defining them anew.
  ~KernelCode() {
    std::lock_guard lock(jit_mutex);
    llvm::consumeError(tracker->remove());
    --resident_kernels;
  }
  std::string name;
  llvm::orc::ResourceTrackerSP tracker;
  KernelBindFunction bind;
  KernelRunFunction run;
  int width;
  std::recursive_mutex& jit_mutex;
};

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
    prune();
  }
  std::unique_ptr<llvm::MemoryBuffer> getObject(const llvm::Module*) override { return nullptr; }
  void set_folder(std::filesystem::path folder, int limit) {
    folder_ = std::move(folder);
    limit_ = limit;
  }

 private:
  // Keeps the folder to limit_ kernel objects, removing the least recently
  // used (written, or read: compile() touches what it reads) first: an
  // editor session compiles a program per edit.
  void prune() const {
    std::error_code error;
    std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> objects;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with("shade_kernel_") && entry.path().extension() == ".o")
        objects.emplace_back(entry.last_write_time(error), entry.path());
    }
    if (objects.size() <= static_cast<std::size_t>(std::max(limit_, 0))) return;
    std::sort(objects.begin(), objects.end());
    for (std::size_t i = 0; i + static_cast<std::size_t>(std::max(limit_, 0)) < objects.size(); ++i)
      std::filesystem::remove(objects[i].second, error);
  }

  std::filesystem::path folder_;
  int limit_ = 0;
};

// One LLJIT for the process. Never destroyed: kernels may outlive every
// static object, and each removes its own code (KernelCode).
class Jit {
 public:
  static Jit& instance() {
    static Jit* jit = new Jit;
    return *jit;
  }

  Result<CompiledKernel> compile(const ShadeIR& ir, int width, const JitSettings& settings) {
    if (!jit_) return failure("cannot start the LLVM JIT (--backend interp still works): " + startup_error_);
    if (width == 0) width = host_vector_width();
    const auto start = std::chrono::steady_clock::now();
    const GatherStrategy gathers = effective_gathers(settings);
    std::string name = kernel_name(canonical_key(ir, width, gathers));
    std::vector<std::shared_ptr<const KernelCode>> evicted;  // released after the lock, which their removal takes
    std::lock_guard lock(mutex_);
    auto elapsed = [&] {
      return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    if (settings.cold) {
      name += "_cold" + std::to_string(++cold_compiles_);
      object_cache_->set_folder({}, 0);
      Result<std::shared_ptr<const KernelCode>> code = build_and_add(ir, width, name, gathers);
      if (!code) return code.error();
      return compiled(*code, CacheHit::none, elapsed());
    }
    if (auto found = resident_.find(name); found != resident_.end())
      if (std::shared_ptr<const KernelCode> code = found->second.lock()) {
        keep_recent(code, evicted);
        return compiled(code, CacheHit::memory, elapsed());
      }
    const std::filesystem::path folder = settings.disk_cache ? cache_folder(settings) : std::filesystem::path();
    object_cache_->set_folder(folder, settings.disk_cache_objects);
    if (!folder.empty()) {
      const std::filesystem::path file = folder / (name + ".o");
      auto object = llvm::MemoryBuffer::getFile(file.string());
      if (object) {
        Result<std::shared_ptr<const KernelCode>> code = add_object(name, width, std::move(*object));
        if (code) {
          std::error_code ignored;  // recently used: the last to be pruned
          std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), ignored);
          return admit(*code, CacheHit::disk, elapsed(), evicted);
        }
      }
    }
    Result<std::shared_ptr<const KernelCode>> code = build_and_add(ir, width, name, gathers);
    if (!code) return code.error();
    return admit(*code, CacheHit::none, elapsed(), evicted);
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

  std::recursive_mutex& mutex() { return mutex_; }

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

  Result<std::shared_ptr<const KernelCode>> build_and_add(const ShadeIR& ir, int width, const std::string& name,
                                                          GatherStrategy gathers) {
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
      return add_object(name, width, std::move(*object));
    }
    llvm::orc::ResourceTrackerSP tracker = jit_->getMainJITDylib().createResourceTracker();
    if (llvm::Error error =
            jit_->addIRModule(tracker, llvm::orc::ThreadSafeModule(std::move(*module), std::move(context))))
      return failure("JIT: " + error_text(std::move(error)));
    return look_up(name, width, tracker);
  }

  Result<std::shared_ptr<const KernelCode>> add_object(const std::string& name, int width,
                                                       std::unique_ptr<llvm::MemoryBuffer> object) {
    llvm::orc::ResourceTrackerSP tracker = jit_->getMainJITDylib().createResourceTracker();
    if (llvm::Error error = jit_->addObjectFile(tracker, std::move(object))) {
      llvm::consumeError(tracker->remove());
      return failure("JIT: " + error_text(std::move(error)));
    }
    return look_up(name, width, tracker);
  }

  // The kernel's two functions, once its module or object is in the JIT
  // under `tracker`; a kernel that cannot be found is removed again.
  Result<std::shared_ptr<const KernelCode>> look_up(const std::string& name, int width,
                                                    const llvm::orc::ResourceTrackerSP& tracker) {
    auto missing = [&](llvm::Error error) -> Diagnostic {
      llvm::consumeError(tracker->remove());
      return failure("JIT: " + error_text(std::move(error)));
    };
    auto bind = jit_->lookup(name + "_bind");
    if (!bind) return missing(bind.takeError());
    auto run = jit_->lookup(name + "_run");
    if (!run) return missing(run.takeError());
    const CompiledKernel functions{bind->toPtr<KernelBindFunction>(), run->toPtr<KernelRunFunction>(), width, 0,
                                   CacheHit::none, nullptr};
    return std::shared_ptr<const KernelCode>(std::make_shared<KernelCode>(name, tracker, functions, mutex_));
  }

  static CompiledKernel compiled(const std::shared_ptr<const KernelCode>& code, CacheHit cache, double milliseconds) {
    return {code->bind, code->run, code->width, milliseconds, cache, code};
  }

  // A new kernel: resident, and the most recently used.
  CompiledKernel admit(const std::shared_ptr<const KernelCode>& code, CacheHit cache, double milliseconds,
                       std::vector<std::shared_ptr<const KernelCode>>& evicted) {
    std::erase_if(resident_, [](const auto& entry) { return entry.second.expired(); });
    resident_[code->name] = code;
    keep_recent(code, evicted);
    return compiled(code, cache, milliseconds);
  }

  // Moves `code` to the front of the memory cache; what falls off its end
  // goes to `evicted`.
  void keep_recent(const std::shared_ptr<const KernelCode>& code,
                   std::vector<std::shared_ptr<const KernelCode>>& evicted) {
    std::erase(recent_, code);
    recent_.insert(recent_.begin(), code);
    while (recent_.size() > static_cast<std::size_t>(memory_cache_kernels)) {
      evicted.push_back(std::move(recent_.back()));
      recent_.pop_back();
    }
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

  std::string startup_error_;
  std::unique_ptr<llvm::TargetMachine> target_machine_;
  std::unique_ptr<llvm::TargetMachine> fast_target_machine_;  // for huge kernels: see build_and_add
  std::unique_ptr<DiskObjectCache> object_cache_;
  std::unique_ptr<llvm::orc::LLJIT> jit_;
  std::recursive_mutex mutex_;  // recursive: a KernelCode may go while a compile holds it
  std::map<std::string, std::weak_ptr<const KernelCode>> resident_;  // every kernel in the JIT, by name
  std::vector<std::shared_ptr<const KernelCode>> recent_;            // the memory cache, most recent first
  int cold_compiles_ = 0;
};

}  // namespace

int host_vector_width() {
  if (host_has("avx512f")) return 16;
  if (host_has("avx2")) return 8;
  return 4;
}

long resident_kernel_count() { return resident_kernels.load(); }

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
