// The interpreted backend: the reference every other backend must match and
// the baseline of every benchmark. Like the Pixel-Planes 5 T-code
// interpreter (Rhoades et al. 1992), it runs one instruction at a time over
// a whole block of samples, so dispatch costs once per block, not per
// sample, and each instruction's inner loop is a tight loop over lanes.
#pragma once

#include <memory>
#include <vector>

#include "ir/kernel.h"

namespace shadetree {

inline constexpr int interpreter_block_size = 256;

std::unique_ptr<Kernel> make_interpreted_kernel(ShadeIR ir);

// Runs a program of uniform instructions that reads no inputs; returns the
// components of its last instruction. The evaluator of constant folding
// (ir/optimize.h).
std::vector<float> evaluate_constant_program(const ShadeIR& program);

}  // namespace shadetree
