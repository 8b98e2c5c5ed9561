// ShadeIR -> LLVM IR for an interval program: interp/interval_program.h's
// evaluation over a box of the varying globals, compiled. One function,
//
//   void NAME(const float* params, const float* uniform_globals,
//             const Interval* box_planes, Interval* output_planes)
//
// where box_planes holds an interval per varying input plane (SampleBox)
// and output_planes one per plane of output_layout(ir), of which the
// bounded outputs' are written. It runs the instructions as the
// interpreter does, each op through its interval form in the op library
// (st_<op>_interval, codegen/ops_bitcode.cpp), so the enclosures are the
// interpreter's to the bit; what differs is that no instruction is
// dispatched, and constants fold into the ops. Its type, as a caller sees
// it, is ir/kernel.h's IntervalProgramFunction.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "ir/shade_ir.h"

namespace llvm {
class LLVMContext;
class Module;
}  // namespace llvm

namespace shadetree {

// Graph data past max_embedded_data_bytes is declared as
// kernel_data_symbol(function_name), as in a kernel's module.
Result<std::unique_ptr<llvm::Module>> emit_interval_module(const ShadeIR& ir, const std::vector<OutputId>& bounded,
                                                           llvm::LLVMContext& context,
                                                           const std::string& function_name);

}  // namespace shadetree
