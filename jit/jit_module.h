// The JIT lives in a loadable module, libshadetree_jit.so (codegen/ and
// jit/ with the parts of LLVM they use, linked in statically): loading it
// costs a process about 25 ms, which commands that compile nothing (check,
// nodes, schema) and farms running thousands of short tasks should not
// pay. The module hands out one table of the JIT's functions;
// jit/jit_calls.cpp loads it on the first call and forwards
// jit_compiler.h's and host_target.h's functions to it. Both sides are
// built from the same sources in one build, so the table passes C++
// types; the version guards against a module left from another build.
#pragma once

#include <optional>
#include <string>

#include "jit/host_target.h"
#include "jit/jit_compiler.h"

namespace shadetree {

inline constexpr int jit_module_version = 2;

struct JitModule {
  int version = jit_module_version;
  Result<CompiledKernel> (*compile_kernel)(const ShadeIR&, int, const JitSettings&);
  std::optional<CompiledKernel> (*cached_kernel)(const ShadeIR&, int, const JitSettings&);
  std::string (*kernel_identity)(const ShadeIR&, int, const JitSettings&);
  Result<CompiledIntervalProgram> (*compile_interval_program)(const ShadeIR&, const std::vector<OutputId>&);
  Result<std::string> (*kernel_listing)(const ShadeIR&, int, Listing, const JitSettings&);
  long (*resident_kernel_count)();
  int (*host_vector_width)();
  GatherStrategy (*host_gather_strategy)();
  bool (*host_has)(const char*);
  std::string (*host_cpu_name)();
  std::string (*host_features)();
};

}  // namespace shadetree

// The module's one exported symbol.
extern "C" const shadetree::JitModule* shadetree_jit_module();
inline constexpr const char* jit_module_entry = "shadetree_jit_module";
