// What a program must compute for some of its outputs only: the
// instructions they depend on, walking back from them through arguments,
// and a conditional region's markers (and so its condition) where the
// region holds one of those. The interval programs bound a volume's
// opacity without its colour's noise this way.
#pragma once

#include <vector>

#include "ir/shade_ir.h"

namespace shadetree {

struct OutputDependencies {
  std::vector<char> instructions;  // per instruction: an output in the list depends on it
  std::vector<char> outputs;       // per output of the program: in the list
};

// For `outputs` (every output of `ir` where the list is empty).
OutputDependencies output_dependencies(const ShadeIR& ir, const std::vector<OutputId>& outputs);

}  // namespace shadetree
