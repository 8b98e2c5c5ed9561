#include "ir/optimize.h"

#include "ir/passes/eliminate_common_subexpressions.h"
#include "ir/passes/eliminate_dead_code.h"
#include "ir/passes/fold_constants.h"
#include "ir/passes/place_conditional_regions.h"

namespace shadetree {

void optimize(ShadeIR& ir, const ConstantEvaluator& evaluate_constants, const PassObserver& observe) {
  auto after = [&](const char* pass) {
    if (observe) observe(pass, ir);
  };
  eliminate_dead_code(ir);
  after("eliminate_dead_code");
  if (evaluate_constants) {
    fold_constants(ir, evaluate_constants);
    after("fold_constants");
  }
  eliminate_common_subexpressions(ir);
  after("eliminate_common_subexpressions");
  eliminate_dead_code(ir);
  after("eliminate_dead_code");
  place_conditional_regions(ir);
  after("place_conditional_regions");
}

}  // namespace shadetree
