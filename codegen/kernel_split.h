// Where a large kernel is split in two, so that it compiles on two threads.
//
// LLVM compiles a module on one thread, and a large kernel's cold compile
// is mostly its back end (instruction selection and register allocation
// over one long loop body). So a kernel whose ops bring more than
// split_threshold library instructions is emitted as two modules compiled
// side by side: the first part evaluates the varying instructions before
// the cut over a chunk of samples and leaves the values the second part
// reads (the crossing values) in a scratch block; the second part reads
// them back and evaluates the rest. The run function calls both, chunk by
// chunk (codegen/emit_kernel.h). A cut lies outside every conditional
// region, where the larger part (its ops and the crossing values it
// stores or loads) weighs least; a kernel with no such cut is compiled
// whole.
#pragma once

#include <optional>
#include <vector>

#include "ir/shade_ir.h"

namespace shadetree {

struct KernelSplit {
  int cut = 0;                // the second part's first instruction
  std::vector<int> crossing;  // values of the first part the second reads, in scratch order
  int crossing_vectors = 0;   // their stored components (vectors per sample)
};

// Samples per chunk: the scratch block holds crossing_vectors of them.
constexpr int kernel_split_chunk = 128;
// What one crossing vector adds to the weight of each part: its store
// in the first, its load in the second (a few instructions each, and
// the scratch block's traffic).
constexpr unsigned crossing_vector_weight = 8;
// More crossing vectors than this and the scratch traffic (and the
// block on the stack) would cost more than the parallel compile saves.
constexpr int max_crossing_vectors = 32;
// Library instructions (op_library_instructions, what the kernel's
// constants leave of its ops) below which a kernel compiles whole. On two
// cores of Zen 3, kernels from here up (turbulence, marble, water_waves)
// compiled in two parts a quarter to a third faster and ran as fast;
// smaller ones (bozo, stf_2d) gained nothing measurable
// (docs/architecture.md, "Each stage of a cold compile").
constexpr unsigned split_threshold = 800;

// Where to split `ir`'s kernel of `width`, or nothing to compile it whole.
std::optional<KernelSplit> kernel_split(const ShadeIR& ir, int width);

}  // namespace shadetree
