#pragma once

#include "ir/optimize.h"

namespace shadetree {

// Replaces every op whose arguments are all constants by its value.
// Preconditions: a verified program without regions; `evaluate` computes
// the last instruction of a program of constants (the interpreter's
// evaluate_constant_program).
void fold_constants(ShadeIR& ir, const ConstantEvaluator& evaluate);

}  // namespace shadetree
