#pragma once

#include "ir/shade_ir.h"

namespace shadetree {

// Moves the instructions only an `if` branch needs into a region that runs
// only for the samples taking that branch.
void place_conditional_regions(ShadeIR& ir);

}  // namespace shadetree
