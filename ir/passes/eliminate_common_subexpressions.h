#pragma once

#include "ir/shade_ir.h"

namespace shadetree {

// Makes every use of a repeated computation read its first occurrence.
void eliminate_common_subexpressions(ShadeIR& ir);

}  // namespace shadetree
