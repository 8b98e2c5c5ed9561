#include "ir/optimize.h"

#include "ir/passes/eliminate_common_subexpressions.h"
#include "ir/passes/eliminate_dead_code.h"
#include "ir/passes/fold_constants.h"
#include "ir/passes/place_conditional_regions.h"

namespace shadetree {

void optimize(ShadeIR& ir, const ConstantEvaluator& evaluate_constants) {
  eliminate_dead_code(ir);
  if (evaluate_constants) fold_constants(ir, evaluate_constants);
  eliminate_common_subexpressions(ir);
  eliminate_dead_code(ir);
  place_conditional_regions(ir);
}

}  // namespace shadetree
