#pragma once

#include "ir/optimize.h"

namespace shadetree {

// Replaces every op whose arguments are all constants by its value.
void fold_constants(ShadeIR& ir, const ConstantEvaluator& evaluate);

}  // namespace shadetree
