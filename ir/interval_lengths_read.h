// Which values an interval program keeps a bound on the length of
// (nodes/ops/interval_lengths.h): those whose length an op reads, directly
// (length, dot and sphere) or through a rule that gives its own vector
// result's length from its arguments' (neg, mul, add and sub) where that
// length is read in turn; normalize's length, always at most 1, where it
// is read. Keeping every vector's length took half again as long to bound
// a volume's empty space (wool, sponge, stf_multi at 512x512).
#pragma once

#include <vector>

#include "ir/shade_ir.h"

namespace shadetree {

// Per instruction: its length is kept.
std::vector<char> interval_lengths_read(const ShadeIR& ir);

}  // namespace shadetree
