#include "jit/jit_compiler.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>
#include <vector>

#include <llvm/ExecutionEngine/Orc/CompileUtils.h>
#include <llvm/ExecutionEngine/Orc/ExecutionUtils.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>
#include <llvm/IR/Module.h>
#include <llvm/Object/ObjectFile.h>
#include <llvm/Support/CommandLine.h>
#include <llvm/Support/ErrorHandling.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Support/xxhash.h>
#include <llvm/Target/TargetMachine.h>

#include "codegen/emit_interval_program.h"
#include "codegen/emit_kernel.h"
#include "codegen/kernel_split.h"
#include "codegen/op_library.h"
#include "jit/host_target.h"
#include "jit/kernel_object_cache.h"
#include "jit/module_halves.h"
#include "platform/user_cache.h"
#include "jit/optimization_pipeline.h"
#include "nodes/noise_tables.h"

namespace shadetree {

namespace {
std::atomic<long> resident_kernels{0};
}  // namespace

// Objects linked into the JIT under a resource tracker of their own, and
// the graph data their code reads past max_embedded_data_bytes.
struct LinkedCode {
  llvm::orc::ResourceTrackerSP tracker;
  std::shared_ptr<const std::vector<float>> data;
};

// Code in the JIT, removed from it with its last holder.
struct ResidentCode {
  ResidentCode(LinkedCode linked, std::recursive_mutex& jit_mutex)
      : linked(std::move(linked)), jit_mutex(jit_mutex) {}
  // Removes the code under the JIT's lock, so a compile of the same
  // program waits until these symbols are gone before defining them anew.
  ~ResidentCode() {
    std::lock_guard lock(jit_mutex);
    llvm::consumeError(linked.tracker->remove());
  }
  ResidentCode(const ResidentCode&) = delete;
  ResidentCode& operator=(const ResidentCode&) = delete;
  LinkedCode linked;
  std::recursive_mutex& jit_mutex;
};

struct KernelCode : ResidentCode {
  KernelCode(std::string name, LinkedCode linked, const CompiledKernel& functions, std::recursive_mutex& jit_mutex)
      : ResidentCode(std::move(linked), jit_mutex), name(std::move(name)), bind(functions.bind), run(functions.run),
        width(functions.width) {
    ++resident_kernels;
  }
  ~KernelCode() { --resident_kernels; }
  std::string name;
  KernelBindFunction bind;
  KernelRunFunction run;
  int width;
};

namespace {

// In-register lookups use AVX-512 instructions: never emit them on a host
// without it, whatever the settings ask for.
GatherStrategy effective_gathers(const JitSettings& settings) {
  const GatherStrategy wanted = settings.gathers.value_or(host_gather_strategy());
  const bool needs_avx512 = wanted == GatherStrategy::in_register ||
                            wanted == GatherStrategy::in_register_byte_permutes ||
                            wanted == GatherStrategy::byte_permutes_and_gathers ||
                            wanted == GatherStrategy::byte_permutes_and_per_lane;
  if (needs_avx512 && host_vector_width() < 16) return GatherStrategy::per_lane;
  if (!host_has("avx512vbmi")) {
    if (wanted == GatherStrategy::in_register_byte_permutes) return GatherStrategy::in_register;
    if (wanted == GatherStrategy::byte_permutes_and_gathers) return GatherStrategy::hardware;
    if (wanted == GatherStrategy::byte_permutes_and_per_lane) return GatherStrategy::per_lane;
  }
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

// A canonical text of everything the machine code depends on.
std::string canonical_key(const ShadeIR& ir, int width, GatherStrategy gathers) {
  std::ostringstream text;
  text << kernel_abi_hash() << " " << op_library_hash() << " " << SHADETREE_CODEGEN_DIGEST << "\n" << width << " " << static_cast<int>(gathers) << "\n" << host_cpu_name() << "\n" << host_features() << "\n";
  return text.str() + program_key_text(ir);
}

// One object file of a kernel, under the name the disk cache keeps it by.
struct KernelObject {
  std::string name;
  std::unique_ptr<llvm::MemoryBuffer> code;
};
// A kernel's object files: its modules' (the one with the bind and run
// functions first, then a split kernel's first part:
// codegen/kernel_split.h), each followed by its half if its code was
// generated in two (jit/module_halves.h).
using KernelObjects = std::vector<KernelObject>;

// Milliseconds of wall time since `start`.
double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The name of kernel `name`'s module `part`.
std::string module_name(const std::string& name, KernelPart part) {
  return part == KernelPart::first ? name + "_first" : name;
}

// The names of the modules of kernel `name`, in that order.
std::vector<std::string> module_names(const std::string& name, const std::optional<KernelSplit>& split) {
  if (!split) return {name};
  return {name, module_name(name, KernelPart::first)};
}

// The name of the function, and of the object, that holds the half of
// module `module_name` compiled apart.
std::string half_name(const std::string& module_name) { return module_name + "_half"; }

// Whether object file `object` calls the function `name` defined
// elsewhere; a file that is no object calls nothing.
bool calls(const llvm::MemoryBuffer& object, const std::string& name) {
  auto file = llvm::object::ObjectFile::createObjectFile(object.getMemBufferRef());
  if (!file) {
    llvm::consumeError(file.takeError());
    return false;
  }
  for (const llvm::object::SymbolRef& symbol : (*file)->symbols()) {
    auto flags = symbol.getFlags();
    auto symbol_name = symbol.getName();
    if (flags && symbol_name && (*flags & llvm::object::SymbolRef::SF_Undefined) && *symbol_name == name) return true;
    if (!flags) llvm::consumeError(flags.takeError());
    if (!symbol_name) llvm::consumeError(symbol_name.takeError());
  }
  return false;
}

std::string kernel_name(const std::string& key) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(llvm::xxh3_64bits(llvm::StringRef(key))));
  return std::string("shade_kernel_") + hex;
}

// One LLJIT for the process. Never destroyed: kernels may outlive every
// static object, and each removes its own code (KernelCode).
// Compiles run outside the lock, each with a target machine of its own, so
// two run in parallel and a cache lookup never waits for one (the editor
// server compiles in the background while it answers from the cache); the
// lock covers linking objects into the JIT and the caches' bookkeeping.
class Jit {
 public:
  static Jit& instance() {
    static Jit* jit = new Jit;
    return *jit;
  }

  Result<CompiledKernel> compile(const ShadeIR& ir, int width, const JitSettings& settings, bool cached_only) {
    if (!jit_) return failure("cannot start the LLVM JIT (--backend interp still works): " + startup_error_);
    if (width == 0) width = host_vector_width();
    const auto start = std::chrono::steady_clock::now();
    const GatherStrategy gathers = effective_gathers(settings);
    std::string name = kernel_name(canonical_key(ir, width, gathers));
    const Optimization optimization = settings.optimization;
    if (settings.cold || optimization == Optimization::quick) {
      if (cached_only) return compiled({}, CacheHit::none, 0);
      name += (optimization == Optimization::quick ? "_quick" : "_cold") + std::to_string(++uncached_compiles_);
      CompileStages stages;
      Result<KernelObjects> objects = compile_objects(ir, width, name, gathers, optimization, stages);
      if (!objects) return objects.error();
      std::lock_guard lock(mutex_);
      Result<std::shared_ptr<const KernelCode>> code = add_objects(ir, name, width, std::move(*objects));
      if (!code) return code.error();
      return compiled(*code, CacheHit::none, milliseconds_since(start), stages);
    }
    const std::filesystem::path folder = settings.disk_cache ? user_cache_folder(settings.cache_folder) : std::filesystem::path();
    std::vector<std::shared_ptr<const KernelCode>> evicted;  // released after the lock, which their removal takes
    {
      std::lock_guard lock(mutex_);
      if (std::shared_ptr<const KernelCode> code = resident(name, evicted))
        return compiled(code, CacheHit::memory, milliseconds_since(start));
      if (!folder.empty()) {
        // Every object of the kernel, or none (the folder is pruned object
        // by object): each module's, and its half's if it calls one.
        KernelObjects objects;
        std::vector<std::filesystem::path> files;
        bool complete = true;
        for (const std::string& module_name : module_names(name, kernel_split(ir, width)))
          for (const std::string& object_name : {module_name, half_name(module_name)}) {
            if (object_name != module_name && !calls(*objects.back().code, object_name)) continue;
            const std::filesystem::path file = folder / (object_name + ".o");
            auto object = llvm::MemoryBuffer::getFile(file.string());
            complete = complete && object;
            if (!complete) break;
            files.push_back(file);
            objects.push_back({object_name, std::move(*object)});
          }
        if (complete) {
          Result<std::shared_ptr<const KernelCode>> code = add_objects(ir, name, width, std::move(objects));
          if (code) {
            std::error_code ignored;  // recently used: the last to be pruned
            for (const std::filesystem::path& file : files)
              std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), ignored);
            return admit(*code, CacheHit::disk, milliseconds_since(start), evicted);
          }
        }
      }
    }
    if (cached_only) return compiled({}, CacheHit::none, 0);
    CompileStages stages;
    Result<KernelObjects> objects = compile_objects(ir, width, name, gathers, optimization, stages);
    if (!objects) return objects.error();
    if (!folder.empty())
      for (const KernelObject& object : *objects)
        store_kernel_object(folder, object.name, object.code->getBuffer(), settings.disk_cache_objects);
    std::lock_guard lock(mutex_);
    // Another thread may have compiled the same program meanwhile.
    if (std::shared_ptr<const KernelCode> code = resident(name, evicted))
      return compiled(code, CacheHit::none, milliseconds_since(start), stages);
    Result<std::shared_ptr<const KernelCode>> code = add_objects(ir, name, width, std::move(*objects));
    if (!code) return code.error();
    return admit(*code, CacheHit::none, milliseconds_since(start), evicted, stages);
  }

  Result<CompiledIntervalProgram> compile_intervals(const ShadeIR& ir, const std::vector<OutputId>& bounded) {
    if (!jit_) return failure("cannot start the LLVM JIT (--backend interp still works): " + startup_error_);
    const auto start = std::chrono::steady_clock::now();
    const std::string name = "shade_bounds_" + std::to_string(++uncached_compiles_);
    llvm::LLVMContext context;
    Result<std::unique_ptr<llvm::Module>> module = emit_interval_module(ir, bounded, context, name);
    if (!module) return module.error();
    {
      Result<LentMachine> machine = lend_machine(code_generation_level(Optimization::full));
      if (!machine) return machine.error();
      optimize_for(**module, **machine, Optimization::full);
    }
    Result<std::unique_ptr<llvm::MemoryBuffer>> object = generate_code(**module, code_generation_level(Optimization::full));
    if (!object) return object.error();
    std::lock_guard lock(mutex_);
    KernelObjects objects;
    objects.push_back({name, std::move(*object)});
    Result<LinkedCode> linked = link(ir, name, std::move(objects));
    if (!linked) return linked.error();
    Result<llvm::orc::ExecutorAddr> evaluate = address_of(name, *linked);
    if (!evaluate) return evaluate.error();
    return CompiledIntervalProgram{
        .evaluate = evaluate->toPtr<IntervalProgramFunction>(),
        .compile_milliseconds = milliseconds_since(start),
        .code = std::make_shared<const ResidentCode>(std::move(*linked), mutex_)};
  }

  // A target machine for the host, at `level`; each compile has its own
  // (a TargetMachine is not safe to share between threads).
  Result<std::unique_ptr<llvm::TargetMachine>> target_machine(llvm::CodeGenOptLevel level) const {
    if (!jit_) return failure("cannot start the LLVM JIT: " + startup_error_);
    llvm::orc::JITTargetMachineBuilder builder = machine_builder_;
    builder.setCodeGenOptLevel(level);
    auto machine = builder.createTargetMachine();
    if (!machine) return failure("JIT: " + error_text(machine.takeError()));
    return std::move(*machine);
  }

 private:
  Jit() : machine_builder_(llvm::Triple()) {
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
    // The list scheduler after register allocation orders instructions for
    // in-order pipelines; on the out-of-order x86 cores it is enabled for
    // (AMD's Zen among them) it changed no kernel's speed and cost a tenth
    // of code generation (docs/architecture.md). LLVM reads it from its
    // options only; should they refuse it, it stays on.
    const char* options[] = {"shadetree", "-post-RA-scheduler=false"};
    llvm::cl::ParseCommandLineOptions(2, options, "", &llvm::nulls());
    auto machine_builder = llvm::orc::JITTargetMachineBuilder::detectHost();
    if (!machine_builder) {
      startup_error_ = error_text(machine_builder.takeError());
      return;
    }
    machine_builder->setCPU(host_cpu_name());
    machine_builder->getFeatures().addFeaturesVector(
        llvm::SubtargetFeatures(host_features()).getFeatures());
    machine_builder_ = *machine_builder;
    auto jit = llvm::orc::LLJITBuilder().setJITTargetMachineBuilder(*machine_builder).create();
    if (!jit) {
      startup_error_ = error_text(jit.takeError());
      return;
    }
    // Generated code may call C runtime helpers (memcpy, memset) that LLVM
    // introduces; resolve them from the process.
    auto process = llvm::orc::DynamicLibrarySearchGenerator::GetForCurrentProcess(
        (*jit)->getDataLayout().getGlobalPrefix());
    if (!process) {
      startup_error_ = error_text(process.takeError());
      return;
    }
    (*jit)->getMainJITDylib().addGenerator(std::move(*process));
    jit_ = std::move(*jit);
  }

  // A target machine at `level`, lent to one compile and kept for the next
  // when the compile lets it go: making one costs as much as compiling a
  // small kernel, and a TargetMachine is not safe to share between
  // threads at once.
  using LentMachine = std::unique_ptr<llvm::TargetMachine, std::function<void(llvm::TargetMachine*)>>;
  Result<LentMachine> lend_machine(llvm::CodeGenOptLevel level) const {
    std::unique_ptr<llvm::TargetMachine> machine;
    {
      std::lock_guard lock(machines_mutex_);
      if (auto idle = idle_machines_.find(level); idle != idle_machines_.end()) {
        machine = std::move(idle->second);
        idle_machines_.erase(idle);
      }
    }
    if (!machine) {
      Result<std::unique_ptr<llvm::TargetMachine>> made = target_machine(level);
      if (!made) return made.error();
      machine = std::move(*made);
    }
    return LentMachine(machine.release(), [this, level](llvm::TargetMachine* returned) {
      std::lock_guard lock(machines_mutex_);
      idle_machines_.emplace(level, std::unique_ptr<llvm::TargetMachine>(returned));
    });
  }

  // The kernel's object files: a kernel past the split threshold as two
  // modules compiled side by side, its first part on a thread of its own
  // (which inherits the calling thread's priority). The time of each stage
  // is added to `stages`.
  Result<KernelObjects> compile_objects(const ShadeIR& ir, int width, const std::string& name, GatherStrategy gathers,
                                        Optimization optimization, CompileStages& stages) const {
    const std::optional<KernelSplit> split = kernel_split(ir, width);
    if (!split) return compile_module(ir, width, name, gathers, optimization, KernelPart::whole, {}, stages);
    std::optional<Result<KernelObjects>> first;
    CompileStages first_stages;
    std::thread first_part([&] {
      first = compile_module(ir, width, name, gathers, optimization, KernelPart::first, *split, first_stages);
    });
    Result<KernelObjects> objects =
        compile_module(ir, width, name, gathers, optimization, KernelPart::second, *split, stages);
    first_part.join();
    stages += first_stages;
    if (!objects) return objects.error();
    if (!*first) return first->error();
    for (KernelObject& object : **first) objects->push_back(std::move(object));
    return objects;
  }

  // The object files of the kernel's module `part`, built on the calling
  // thread; a large enough module has about half of it compiled on a
  // thread of its own (jit/module_halves.h).
  Result<KernelObjects> compile_module(const ShadeIR& ir, int width, const std::string& name, GatherStrategy gathers,
                                       Optimization optimization, KernelPart part, const KernelSplit& split,
                                       CompileStages& stages) const {
    const std::string half = half_name(module_name(name, part));
    llvm::LLVMContext context;
    Result<std::unique_ptr<llvm::Module>> module =
        optimized_module(ir, width, context, name, gathers, optimization, part, split, stages);
    if (!module) return module.error();
    // Instruction selection, scheduling and greedy register allocation grow
    // faster than the kernel: a 4000-instruction graph spent 2 s there. A
    // kernel this large is compiled with the fast, linear path instead
    // (slower code, a compile in a fraction of the time), both its halves.
    const llvm::CodeGenOptLevel level = (*module)->getInstructionCount() > max_instructions_for_full_codegen
                                            ? llvm::CodeGenOptLevel::None
                                            : code_generation_level(optimization);
    const auto generating = std::chrono::steady_clock::now();
    std::optional<llvm::SmallVector<char, 0>> half_bitcode;
    if (optimization == Optimization::full) half_bitcode = split_off_half(**module, half);
    std::optional<Result<std::unique_ptr<llvm::MemoryBuffer>>> half_object;
    double half_milliseconds = 0;
    std::thread half_thread;
    if (half_bitcode)
      half_thread = std::thread([&] {
        const auto start = std::chrono::steady_clock::now();
        llvm::LLVMContext half_context;
        Result<std::unique_ptr<llvm::Module>> half_code =
            half_module(llvm::StringRef(half_bitcode->data(), half_bitcode->size()), half, half_context);
        half_object = half_code ? generate_code(**half_code, level) : half_code.error();
        half_milliseconds = milliseconds_since(start);
      });
    Result<std::unique_ptr<llvm::MemoryBuffer>> object = generate_code(**module, level);
    stages.generate_milliseconds += milliseconds_since(generating);
    ++stages.modules;
    if (half_thread.joinable()) {
      half_thread.join();
      stages.generate_milliseconds += half_milliseconds;
      ++stages.modules;
    }
    if (!object) return object.error();
    KernelObjects objects;
    objects.push_back({module_name(name, part), std::move(*object)});
    if (half_object) {
      if (!*half_object) return half_object->error();
      objects.push_back({half, std::move(**half_object)});
    }
    return objects;
  }

  // The module of the kernel's `part`, optimized with a target machine lent
  // for the purpose.
  Result<std::unique_ptr<llvm::Module>> optimized_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                         const std::string& name, GatherStrategy gathers,
                                                         Optimization optimization, KernelPart part,
                                                         const KernelSplit& split, CompileStages& stages) const {
    Result<LentMachine> machine = lend_machine(code_generation_level(optimization));
    if (!machine) return machine.error();
    return build_optimized_module(ir, width, context, name, gathers, **machine, optimization, part, split, &stages);
  }

  // The machine code of `module`, built on the calling thread.
  Result<std::unique_ptr<llvm::MemoryBuffer>> generate_code(llvm::Module& module, llvm::CodeGenOptLevel level) const {
    Result<LentMachine> machine = lend_machine(level);
    if (!machine) return machine.error();
    auto object = llvm::orc::SimpleCompiler(**machine)(module);
    if (!object) return failure("JIT: " + error_text(object.takeError()));
    return std::move(*object);
  }

  // Links the kernel's objects, and binds the data they declare (large
  // data, codegen/emit_kernel.h) to a copy the kernel keeps.
  Result<std::shared_ptr<const KernelCode>> add_objects(const ShadeIR& ir, const std::string& name, int width,
                                                        KernelObjects objects) {
    Result<LinkedCode> linked = link(ir, name, std::move(objects));
    if (!linked) return linked.error();
    return look_up(name, width, std::move(*linked));
  }

  // Objects linked under a resource tracker of their own, with the data
  // they declare (large data, codegen/emit_kernel.h) bound to a copy;
  // nothing is left in the JIT on failure.
  Result<LinkedCode> link(const ShadeIR& ir, const std::string& name, KernelObjects objects) {
    LinkedCode linked{jit_->getMainJITDylib().createResourceTracker(), nullptr};
    if (ir.data.size() * sizeof(float) > max_embedded_data_bytes) {
      linked.data = std::make_shared<const std::vector<float>>(ir.data);
      const llvm::orc::SymbolMap symbols{
          {jit_->mangleAndIntern(kernel_data_symbol(name)),
           {llvm::orc::ExecutorAddr::fromPtr(linked.data->data()), llvm::JITSymbolFlags::Exported}}};
      if (llvm::Error error = linked.tracker->getJITDylib().define(llvm::orc::absoluteSymbols(symbols), linked.tracker)) {
        llvm::consumeError(linked.tracker->remove());
        return failure("JIT: " + error_text(std::move(error)));
      }
    }
    for (KernelObject& object : objects)
      if (llvm::Error error = jit_->addObjectFile(linked.tracker, std::move(object.code))) {
        llvm::consumeError(linked.tracker->remove());
        return failure("JIT: " + error_text(std::move(error)));
      }
    return linked;
  }

  // The address of `symbol` in linked code; code whose symbol cannot be
  // found is removed again.
  Result<llvm::orc::ExecutorAddr> address_of(const std::string& symbol, const LinkedCode& linked) {
    auto address = jit_->lookup(symbol);
    if (address) return *address;
    llvm::consumeError(linked.tracker->remove());
    return failure("JIT: " + error_text(address.takeError()));
  }

  // The kernel's two functions, once its objects are linked.
  Result<std::shared_ptr<const KernelCode>> look_up(const std::string& name, int width, LinkedCode linked) {
    Result<llvm::orc::ExecutorAddr> bind = address_of(name + "_bind", linked);
    if (!bind) return bind.error();
    Result<llvm::orc::ExecutorAddr> run = address_of(name + "_run", linked);
    if (!run) return run.error();
    const CompiledKernel functions{
        .bind = bind->toPtr<KernelBindFunction>(), .run = run->toPtr<KernelRunFunction>(), .width = width};
    return std::shared_ptr<const KernelCode>(std::make_shared<KernelCode>(name, std::move(linked), functions, mutex_));
  }

  static CompiledKernel compiled(const std::shared_ptr<const KernelCode>& code, CacheHit cache, double milliseconds,
                                 const CompileStages& stages = {}) {
    if (!code) return {};
    return {.bind = code->bind,
            .run = code->run,
            .width = code->width,
            .compile_milliseconds = milliseconds,
            .stages = stages,
            .cache = cache,
            .code = code};
  }

  // The kernel `name` if it is in the JIT, made the most recently used.
  std::shared_ptr<const KernelCode> resident(const std::string& name,
                                             std::vector<std::shared_ptr<const KernelCode>>& evicted) {
    auto found = resident_.find(name);
    if (found == resident_.end()) return nullptr;
    std::shared_ptr<const KernelCode> code = found->second.lock();
    if (code) keep_recent(code, evicted);
    return code;
  }

  // A new kernel: resident, and the most recently used.
  CompiledKernel admit(const std::shared_ptr<const KernelCode>& code, CacheHit cache, double milliseconds,
                       std::vector<std::shared_ptr<const KernelCode>>& evicted, const CompileStages& stages = {}) {
    std::erase_if(resident_, [](const auto& entry) { return entry.second.expired(); });
    resident_[code->name] = code;
    keep_recent(code, evicted);
    return compiled(code, cache, milliseconds, stages);
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

  std::string startup_error_;
  llvm::orc::JITTargetMachineBuilder machine_builder_;  // the host, with all its features
  std::unique_ptr<llvm::orc::LLJIT> jit_;
  std::recursive_mutex mutex_;  // recursive: a KernelCode may go while the lock is held
  std::map<std::string, std::weak_ptr<const KernelCode>> resident_;  // every kernel in the JIT, by name
  std::vector<std::shared_ptr<const KernelCode>> recent_;            // the memory cache, most recent first
  std::atomic<int> uncached_compiles_{0};  // cold and quick: each under a name of its own
  mutable std::mutex machines_mutex_;
  mutable std::multimap<llvm::CodeGenOptLevel, std::unique_ptr<llvm::TargetMachine>> idle_machines_;  // lent by lend_machine
};

}  // namespace

long resident_kernel_count() { return resident_kernels.load(); }

Result<CompiledKernel> compile_kernel(const ShadeIR& ir, int width, const JitSettings& settings) {
  Result<CompiledKernel> compiled = Jit::instance().compile(ir, width, settings, false);
  if (compiled) compiled->state_size = uniform_state_layout(ir).size;
  return compiled;
}

Result<CompiledIntervalProgram> compile_interval_program(const ShadeIR& ir, const std::vector<OutputId>& bounded) {
  return Jit::instance().compile_intervals(ir, bounded);
}

std::string kernel_identity(const ShadeIR& ir, int width, const JitSettings& settings) {
  if (width == 0) width = host_vector_width();
  return kernel_name(canonical_key(ir, width, effective_gathers(settings)));
}

std::optional<CompiledKernel> cached_kernel(const ShadeIR& ir, int width, const JitSettings& settings) {
  Result<CompiledKernel> found = Jit::instance().compile(ir, width, settings, true);
  if (!found || !found->code) return std::nullopt;
  found->state_size = uniform_state_layout(ir).size;
  return *found;
}

namespace {

// `module` as assembly for `machine`, or as LLVM IR.
Result<std::string> listing_of(llvm::Module& module, Listing listing, llvm::TargetMachine& machine) {
  if (listing == Listing::assembly) return assembly(module, machine);
  std::string text;
  llvm::raw_string_ostream stream(text);
  module.print(stream, nullptr);
  return text;
}

}  // namespace

Result<std::string> kernel_listing(const ShadeIR& ir, int width, Listing listing, const JitSettings& settings) {
  if (width == 0) width = host_vector_width();
  Result<std::unique_ptr<llvm::TargetMachine>> machine =
      Jit::instance().target_machine(code_generation_level(settings.optimization));
  if (!machine) return machine.error();
  // A split kernel's modules one after the other, each under a heading.
  const std::optional<KernelSplit> split = kernel_split(ir, width);
  const std::vector<KernelPart> parts =
      split ? std::vector<KernelPart>{KernelPart::first, KernelPart::second} : std::vector<KernelPart>{KernelPart::whole};
  const char* comment = listing == Listing::assembly ? "#" : ";";
  std::string text;
  for (KernelPart part : parts) {
    if (split)
      text += std::string(comment) + " module " + (part == KernelPart::first ? "1" : "2") +
              " of 2: the kernel split before instruction %" + std::to_string(split->cut) + "\n";
    llvm::LLVMContext context;
    Result<std::unique_ptr<llvm::Module>> module =
        build_optimized_module(ir, width, context, "shade_kernel", effective_gathers(settings), **machine,
                               settings.optimization, part, split.value_or(KernelSplit{}));
    if (!module) return module.error();
    // A module whose code is generated in two halves, then its half.
    const std::string half = half_name(module_name("shade_kernel", part));
    std::optional<llvm::SmallVector<char, 0>> half_bitcode;
    if (settings.optimization == Optimization::full) half_bitcode = split_off_half(**module, half);
    Result<std::string> listed = listing_of(**module, listing, **machine);
    if (!listed) return listed.error();
    text += *listed;
    if (!half_bitcode) continue;
    llvm::LLVMContext half_context;
    Result<std::unique_ptr<llvm::Module>> half_code =
        half_module(llvm::StringRef(half_bitcode->data(), half_bitcode->size()), half, half_context);
    if (!half_code) return half_code.error();
    text += std::string(comment) + " the half of this module compiled on a thread of its own\n";
    listed = listing_of(**half_code, listing, **machine);
    if (!listed) return listed.error();
    text += *listed;
  }
  return text;
}

}  // namespace shadetree
