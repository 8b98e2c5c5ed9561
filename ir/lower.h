// Stage 3: CheckedGraph -> ShadeIR. Inlines user-defined functions, turns
// implicit conversions into component reads, lays out params in a uniform
// block and marks uniform values. The result is one instruction per node
// use, unoptimized: ir/optimize.h comes next.
#pragma once

#include "graph/check.h"
#include "graph/diagnostic.h"
#include "ir/shade_ir.h"

namespace shadetree {

// Inlining can multiply a small file into a huge program (functions that
// call functions twice over); past this many instructions lowering stops
// with a diagnostic instead of exhausting memory.
inline constexpr std::size_t max_program_instructions = 50000;

Result<ShadeIR> lower(const CheckedGraph& graph);

// The uniform block for a graph's params: their defaults.
std::vector<float> param_block(const Graph& graph, const ShadeIR& ir);

}  // namespace shadetree
