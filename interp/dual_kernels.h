// The dual form of every library op, generated from the op list: its
// generic evaluate instantiated over duals (nodes/dual_frame.h), lane by
// lane, for the instructions that differentiation made dual.
#pragma once

// First: the dual primitives must be declared before the semantics that
// call them qualified (lanes::select).
#include "nodes/dual_frame.h"

#include "interp/exec_context.h"

namespace shadetree::interp {

// in[12a + 4c + k] is part k of component c of argument a, out[4c + k] of
// the result (see DualLaneFrame). Null where op_kernel is.
OpKernel dual_op_kernel(OpId op);

}  // namespace shadetree::interp
