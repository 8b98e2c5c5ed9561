// The module's table of the JIT's functions (jit/jit_module.h).
#include "jit/jit_module.h"

extern "C" __attribute__((visibility("default"))) const shadetree::JitModule* shadetree_jit_module() {
  using namespace shadetree;
  static const JitModule module{
      .compile_kernel = &compile_kernel,
      .cached_kernel = &cached_kernel,
      .kernel_identity = &kernel_identity,
      .compile_interval_program = &compile_interval_program,
      .kernel_listing = &kernel_listing,
      .resident_kernel_count = &resident_kernel_count,
      .host_vector_width = &host_vector_width,
      .host_gather_strategy = &host_gather_strategy,
      .host_has = &host_has,
      .host_cpu_name = &host_cpu_name,
      .host_features = &host_features,
  };
  return &module;
}
