#pragma once

#include "ir/shade_ir.h"

namespace shadetree {

// Makes every use of a repeated computation read its first occurrence.
// Preconditions: a verified program without regions (an instruction inside
// one may not stand for one outside it); ops are pure.
void eliminate_common_subexpressions(ShadeIR& ir);

}  // namespace shadetree
