// ShadeIR -> LLVM IR: two functions per kernel, for bind once, run many
// (ir/kernel.h):
//
//   void NAME_bind(const float* params, const float* uniform_globals,
//                  float* state)
//     computes every uniform value that is not a constant into `state`;
//   void NAME_run(const float* state, const float* const* input_planes,
//                 float* const* output_planes, int64_t count)
//     evaluates the varying code over `count` samples (a multiple of the
//     vector width), `width` samples at a time as <width x float> vectors.
//
// uniform_globals and input_planes follow the globals table
// (nodes/globals.h); output_planes the graph kind's output layout. A large
// kernel is emitted as two modules instead (KernelPart below), whose
// NAME_bind and NAME_run are the same functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "codegen/kernel_split.h"
#include "graph/diagnostic.h"
#include "ir/kernel.h"
#include "ir/shade_ir.h"

namespace llvm {
class LLVMContext;
class Module;
}  // namespace llvm

namespace shadetree {

using KernelBindFunction = void (*)(const float* params, const float* uniform_globals, float* state);
using KernelRunFunction = void (*)(const float* state, const float* const* input_planes, float* const* output_planes,
                                   std::int64_t count);

// Where the bind function leaves each uniform value (-1: not kept, as
// constants are emitted where they are used), and the floats it needs.
struct UniformStateLayout {
  std::vector<int> slots;  // per instruction: first float in the state block
  int size = 0;
};
UniformStateLayout uniform_state_layout(const ShadeIR& ir);

// How the op library's table lookups become instructions: one hardware
// gather per lookup (vgatherdps / vpgatherdd); one scalar load per lane; or,
// at width 16 (AVX-512), permutes over the 256-entry noise tables held in
// registers and hardware gathers for the other tables (splines); the same
// with the noise permutation looked up as bytes (AVX-512 VBMI); or the
// permutation as bytes and every float table by hardware gathers; or the
// permutation as bytes (the lattice's rows hashed by it for all lanes at
// once, a periodic noise's in general registers as per-lane does), the
// gradients one lane at a time, and tables of other sizes by hardware
// gathers. Spline knots (up to 32 floats) are in
// registers in the last four.
enum class GatherStrategy {
  hardware,
  per_lane,
  in_register,
  in_register_byte_permutes,
  byte_permutes_and_gathers,
  byte_permutes_and_per_lane
};

// Which module of a kernel to emit: the whole kernel, or a part of one
// split in two (codegen/kernel_split.h). The first part's module defines
//   void NAME_first(const float* state, const float* const* input_planes,
//                   float* const* output_planes, float* scratch,
//                   int64_t start, int64_t end);
// the second's defines NAME_bind and NAME_run, which calls NAME_first.
enum class KernelPart { whole, first, second };

// Graph data larger than this (images, meshes) is not written into a
// kernel's module: the module declares it as `function_name` + "_data",
// which whoever links the kernel binds to a copy of `ShadeIR::data` (the
// JIT, jit/jit_compiler.cpp), so that a compile does not copy it through
// a constant, an object and a linked segment.
inline constexpr std::size_t max_embedded_data_bytes = 64 * 1024;

// The symbol of a kernel's data past max_embedded_data_bytes.
inline std::string kernel_data_symbol(const std::string& function_name) { return function_name + "_data"; }

// The module holds the kernel's functions (`function_name` + "_bind" and
// "_run", or the part's) and the op library they call, marked for
// inlining. `split` says where a part begins and ends.
Result<std::unique_ptr<llvm::Module>> emit_kernel_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                         const std::string& function_name,
                                                         GatherStrategy gathers = GatherStrategy::hardware,
                                                         KernelPart part = KernelPart::whole,
                                                         const KernelSplit& split = {});

}  // namespace shadetree
