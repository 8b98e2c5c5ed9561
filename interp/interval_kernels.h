// The interval form of every library op, generated from the op list:
// the op's own evaluate_interval where it states one, else its generic
// evaluate instantiated over intervals (nodes/interval_frame.h).
#pragma once

#include "nodes/interval_frame.h"
#include "nodes/op_id.h"

namespace shadetree::interp {

using IntervalKernel = void (*)(const IntervalFrame& frame);

// Null for the ops that lowering replaces (inputs and split), as for
// op_kernel (interp/exec_context.h).
IntervalKernel interval_kernel(OpId op);

}  // namespace shadetree::interp
