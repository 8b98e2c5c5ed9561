// ShadeIR -> LLVM IR: one kernel function that evaluates the program over
// `count` samples (a multiple of the vector width), `width` samples at a
// time as <width x float> vectors.
//
//   void kernel(const float* params, const float* const* input_planes,
//               float time, float frame, float* const* output_planes,
//               int64_t count)
//
// input_planes: the InputPlane order of ir/kernel.h.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "graph/diagnostic.h"
#include "ir/kernel.h"
#include "ir/shade_ir.h"

namespace llvm {
class LLVMContext;
class Module;
}  // namespace llvm

namespace shadetree {

using KernelFunction = void (*)(const float* params, const float* const* input_planes, float time, float frame,
                                float* const* output_planes, std::int64_t count);

// How the op library's table lookups become instructions: one hardware
// gather per lookup (vgatherdps / vpgatherdd); one scalar load per lane; or,
// at width 16 (AVX-512), permutes over the 256-entry noise tables held in
// registers and hardware gathers for the other tables (splines); the last
// also looks the noise permutation up as bytes (AVX-512 VBMI).
enum class GatherStrategy { hardware, per_lane, in_register, in_register_byte_permutes };

// The module holds the kernel (named `function_name`) and the op library it
// calls, marked for inlining.
Result<std::unique_ptr<llvm::Module>> emit_kernel_module(const ShadeIR& ir, int width, llvm::LLVMContext& context,
                                                         const std::string& function_name,
                                                         GatherStrategy gathers = GatherStrategy::hardware);

}  // namespace shadetree
