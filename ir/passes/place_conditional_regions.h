#pragma once

#include "ir/shade_ir.h"

namespace shadetree {

// Moves the instructions only an `if` branch needs into a region that runs
// only for the samples taking that branch.
// Preconditions: a verified program with no regions yet (it runs last, once);
// dead code already removed, so that every instruction has a use.
void place_conditional_regions(ShadeIR& ir);

}  // namespace shadetree
