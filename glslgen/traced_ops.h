// Every op's semantics over traced lanes (nodes/lane_trace.h): calling an
// op's entry writes the GLSL that computes its result to the active Trace
// and leaves the result's names in `result`. Generated from the op list,
// so a new op reaches GLSL with no edit here; instantiating every op is
// the static check that each one traces.
#pragma once

#include "nodes/lane_dual.h"
#include "nodes/lane_trace.h"
#include "nodes/op_frame.h"
#include "nodes/op_id.h"

namespace shadetree {

using TracedDual = lanes::Dual<lanes::TraceF>;

using TracedOp = void (*)(const OpConstants& constants, const lanes::TraceF* const* args, lanes::TraceF* result);
using TracedDualOp = void (*)(const OpConstants& constants, const TracedDual* const* args, TracedDual* result);

// Null for the ops lowered to other instructions (the inputs, split).
TracedOp traced_op(OpId op);
TracedDualOp traced_dual_op(OpId op);

}  // namespace shadetree
