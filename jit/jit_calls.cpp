// The JIT's functions as the rest of shadetree calls them: each loads the
// module (jit/jit_module.h) on first use and forwards to it. A missing or
// stale module is one error line from whatever tried to compile.
#include <atomic>

#include "jit/jit_module.h"
#include "platform/loadable_module.h"

namespace shadetree {
namespace {

struct LoadedJit {
  const JitModule* functions = nullptr;
  std::string error;
};

std::atomic<const JitModule*> loaded_functions{nullptr};

const LoadedJit& loaded_jit() {
  static const LoadedJit jit = [] {
    LoadedJit loaded;
    LoadableModule module{"libshadetree_jit.so", "the JIT"};
    auto* entry = module.function<const JitModule*()>(jit_module_entry);
    if (!entry) {
      loaded.error = module.error() + " (--backend interp still works)";
      return loaded;
    }
    const JitModule* functions = entry();
    if (functions->version != jit_module_version) {
      loaded.error = "the JIT module " + support_file_path("libshadetree_jit.so") +
                     " is from another build of shadetree (--backend interp still works)";
      return loaded;
    }
    loaded.functions = functions;
    loaded_functions.store(functions);
    return loaded;
  }();
  return jit;
}

// The module's functions, or null when it cannot be loaded.
const JitModule* jit() { return loaded_jit().functions; }

Diagnostic jit_missing() { return failure(loaded_jit().error); }

}  // namespace

Result<CompiledKernel> compile_kernel(const ShadeIR& ir, int width, const JitSettings& settings) {
  if (!jit()) return jit_missing();
  return jit()->compile_kernel(ir, width, settings);
}

std::optional<CompiledKernel> cached_kernel(const ShadeIR& ir, int width, const JitSettings& settings) {
  if (!jit()) return std::nullopt;
  return jit()->cached_kernel(ir, width, settings);
}

std::string kernel_identity(const ShadeIR& ir, int width, const JitSettings& settings) {
  return jit() ? jit()->kernel_identity(ir, width, settings) : std::string();
}

Result<CompiledIntervalProgram> compile_interval_program(const ShadeIR& ir, const std::vector<OutputId>& bounded) {
  if (!jit()) return jit_missing();
  return jit()->compile_interval_program(ir, bounded);
}

Result<std::string> kernel_listing(const ShadeIR& ir, int width, Listing listing, const JitSettings& settings) {
  if (!jit()) return jit_missing();
  return jit()->kernel_listing(ir, width, listing, settings);
}

// Counting kernels loads nothing: without the module there are none.
long resident_kernel_count() {
  const JitModule* functions = loaded_functions.load();
  return functions ? functions->resident_kernel_count() : 0;
}

// Without the module nothing compiles, so the host's answers matter only
// for messages: the narrowest width and no features.
int host_vector_width() { return jit() ? jit()->host_vector_width() : 4; }

GatherStrategy host_gather_strategy() { return jit() ? jit()->host_gather_strategy() : GatherStrategy::per_lane; }

bool host_has(const char* feature) { return jit() && jit()->host_has(feature); }

std::string host_cpu_name() { return jit() ? jit()->host_cpu_name() : "unknown"; }

std::string host_features() { return jit() ? jit()->host_features() : std::string(); }

}  // namespace shadetree
