#pragma once

#include "ir/shade_ir.h"

namespace shadetree {

// Removes instructions no output depends on, keeping the order of the rest.
void eliminate_dead_code(ShadeIR& ir);

}  // namespace shadetree
