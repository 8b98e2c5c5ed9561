// Forward-mode differentiation with respect to P, for the `gradient` and
// `bump` nodes. The instructions a value is computed from that depend on P
// get a dual twin (IrInstr::dual): the same op evaluated over dual numbers
// (nodes/lane_dual.h), so each op's derivative comes from its one lane
// form, with no derivative rules written here. A `partials` instruction
// then reads the value's gradient off its twin. Values that do not depend
// on P (params, constants, N, uv...) are read with zero partials, so only
// the part of the graph the gradient needs is made dual.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ir/shade_ir.h"

namespace shadetree {

class Differentiator {
 public:
  explicit Differentiator(ShadeIR& ir) : ir_(ir) {}

  // Appends what the gradient of `value` (a float) needs and returns the
  // vec3 holding it: zero where value does not depend on P. Twins made for
  // one gradient serve the next.
  std::int32_t gradient(std::int32_t value, const std::string& source);

 private:
  std::int32_t append(IrInstr instr);

  ShadeIR& ir_;
  std::vector<std::int32_t> twin_;  // per instruction: its dual twin, or -1
};

}  // namespace shadetree
