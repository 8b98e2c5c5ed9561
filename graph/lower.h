// Stage 3: CheckedGraph -> ShadeIR. Inlines user-defined functions, turns
// implicit conversions into component reads, lays out params in a uniform
// block and marks uniform values. The result is one instruction per node
// use, unoptimized: graph/optimize.h comes next.
#pragma once

#include "graph/check.h"
#include "graph/diagnostic.h"
#include "graph/shade_ir.h"

namespace shadetree {

Result<ShadeIR> lower(const CheckedGraph& graph);

// The uniform block for a graph's params: defaults, with `overrides`
// (param index -> value) applied.
std::vector<float> param_block(const Graph& graph, const ShadeIR& ir);

}  // namespace shadetree
