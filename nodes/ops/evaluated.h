// Which ops have semantics over frames; the others (the input ops and
// split) are lowered to other instructions.
#pragma once

#include "nodes/ops/all.h"

namespace shadetree::ops {

template <class Op, class Frame>
concept Evaluated = requires(const Frame& x) { Op::evaluate(x); };

}  // namespace shadetree::ops
