// ORC LLJIT for shade kernels: host CPU (jit/host_target.h), full
// pipeline or a quick one (jit/optimization_pipeline.h), and two caches.
// In memory, compiled kernels are kept by a hash of the optimized ShadeIR
// (and width and CPU), so a second compile of the same graph is a lookup;
// params are passed at call time, so changing one reuses the machine code.
// Each kernel's code has an ORC ResourceTracker of its own and is removed
// from the JIT once neither the cache nor any Kernel holds it.
// On disk (jit/kernel_object_cache.h), each kernel's object file is kept so
// that a second run of the same graph skips compilation altogether.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "codegen/emit_kernel.h"
#include "graph/diagnostic.h"
#include "ir/shade_ir.h"
#include "ir/kernel.h"
#include "jit/host_target.h"

namespace shadetree {

enum class CacheHit { none, memory, disk };

// A kernel's machine code in the JIT (jit_compiler.cpp), released from
// it when the last CompiledKernel holding it (the memory cache's or a
// Kernel's) goes.
struct KernelCode;

// Where a compile's time went: milliseconds of thread time in each stage,
// summed over the threads that ran it (a split kernel's two parts, and a
// module's half, run side by side: codegen/kernel_split.h,
// jit/module_halves.h), so the stages may add up to more than the
// compile's wall time. All zero where the kernel came from a cache.
struct CompileStages {
  double emit_milliseconds = 0;      // the kernel's LLVM IR, the op library read in
  double optimize_milliseconds = 0;  // the middle end (jit/optimization_pipeline.h)
  double generate_milliseconds = 0;  // a module's half cut off, instruction selection, register allocation, objects
  int modules = 0;                   // modules whose code was generated, each on a thread of its own

  CompileStages& operator+=(const CompileStages& other) {
    emit_milliseconds += other.emit_milliseconds;
    optimize_milliseconds += other.optimize_milliseconds;
    generate_milliseconds += other.generate_milliseconds;
    modules += other.modules;
    return *this;
  }
};

struct CompiledKernel {
  KernelBindFunction bind = nullptr;
  KernelRunFunction run = nullptr;
  int width = 0;
  int state_size = 0;  // floats bind leaves for run (codegen/emit_kernel.h)
  double compile_milliseconds = 0;
  CompileStages stages;
  CacheHit cache = CacheHit::none;
  std::shared_ptr<const KernelCode> code;  // keeps bind and run callable
};

// The memory cache holds the kernels of this many programs, the most
// recently used; older ones stay in the JIT only while a Kernel uses them,
// so a long-running process (shadetree serve) does not grow without bound.
inline constexpr int memory_cache_kernels = 64;

// Kernels whose machine code is in the JIT now (cached or in use).
long resident_kernel_count();

// How hard the JIT works on a kernel. full: a pipeline that does what O3
// does to a kernel and the optimizing code generator, for everything that
// runs for long. quick: the op library inlined and cleaned up (SROA, CSE,
// CFG, dead code) and the fast code generator, in about half the time, for
// code about 0.9x as fast (docs/architecture.md): an editor's first
// preview of an edit,
// until the full kernel is ready (pipeline/tiered_kernel.h). Quick kernels
// are never cached.
enum class Optimization { full, quick };

struct JitSettings {
  bool disk_cache = true;
  std::string cache_folder;  // empty: $SHADETREE_CACHE_DIR, else $XDG_CACHE_HOME/shadetree, else ~/.cache/shadetree
  bool cold = false;         // bypass both caches and compile anew (for measurements)
  std::optional<GatherStrategy> gathers;  // empty: the host's best (docs/architecture.md)
  int disk_cache_objects = 4096;  // the folder keeps this many kernels, the most recently used
  Optimization optimization = Optimization::full;
};

// Compiles (or finds) the kernel for `ir` at `width` (0: host width).
// Thread-safe, and compiles run in parallel. LLVM failures come back as
// diagnostics with status 1.
Result<CompiledKernel> compile_kernel(const ShadeIR& ir, int width, const JitSettings& settings = {});

// The kernel for `ir` if it is in the memory or the disk cache (never with
// JitSettings::cold or a quick optimization); compiles nothing.
std::optional<CompiledKernel> cached_kernel(const ShadeIR& ir, int width, const JitSettings& settings = {});

// The name the JIT knows the kernel of `ir` by: equal for two programs
// exactly when they compile to the same machine code.
std::string kernel_identity(const ShadeIR& ir, int width, const JitSettings& settings = {});

// An interval program compiled (codegen/emit_interval_program.h): the
// enclosures of `bounded` outputs (every output where empty) over a box
// of the varying globals, the interpreter's to the bit.
struct CompiledIntervalProgram {
  IntervalProgramFunction evaluate = nullptr;
  double compile_milliseconds = 0;
  std::shared_ptr<const void> code;  // keeps evaluate callable
};

// Compiles the interval program of `ir` anew each time (a renderer
// compiles one a frame or a sequence); the full pipeline.
Result<CompiledIntervalProgram> compile_interval_program(const ShadeIR& ir, const std::vector<OutputId>& bounded);

// The kernel's optimized LLVM IR, or its assembly.
enum class Listing { optimized_llvm_ir, assembly };
Result<std::string> kernel_listing(const ShadeIR& ir, int width, Listing listing, const JitSettings& settings = {});

}  // namespace shadetree
