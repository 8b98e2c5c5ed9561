// Stage 3: CheckedGraph -> ShadeIR. Inlines user-defined functions, turns
// implicit conversions into component reads, lays out params in a uniform
// block, then runs the passes every backend relies on (dead code
// elimination, conditional region placement).
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
