#pragma once

#include "ir/shade_ir.h"

namespace shadetree {

// Removes instructions no output depends on, keeping the order of the rest.
// Preconditions: a verified program (ir/verify.h) without regions: it runs
// before place_conditional_regions.
void eliminate_dead_code(ShadeIR& ir);

}  // namespace shadetree
