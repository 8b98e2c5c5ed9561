// The graph-level optimizer: the passes every backend benefits from, run on
// freshly lowered ShadeIR in this order:
//   eliminate_dead_code, fold_constants, eliminate_common_subexpressions,
//   eliminate_dead_code, place_conditional_regions.
// Uniform values (those depending only on params and constants) are not a
// pass of their own: lowering marks them and backends compute them once per
// call, not per sample.
#pragma once

#include <functional>
#include <vector>

#include "ir/shade_ir.h"

namespace shadetree {

// Runs a program that reads no inputs and returns the components of its
// last instruction: how constant folding computes values (the interpreter provides
// it, so folded values are exactly what a backend would compute).
using ConstantEvaluator = std::function<std::vector<float>(const ShadeIR& program)>;

// Called with each pass's name and the program after it: to print the
// program after each pass (shadetree emit --graph --after-each-pass) or to
// verify it (ir/verify.h).
using PassObserver = std::function<void(const char* pass, const ShadeIR& ir)>;

// Without an evaluator, constants are not folded.
void optimize(ShadeIR& ir, const ConstantEvaluator& evaluate_constants, const PassObserver& observe = {});

}  // namespace shadetree
