#include "glslgen/traced_ops.h"

// After the traced primitives, which the dual templates call.
#include "nodes/dual_frame.h"
#include "nodes/ops/evaluated.h"
#include "nodes/ops/op_table.h"

namespace shadetree {
namespace {

using lanes::TraceF;

template <class Op>
void trace(const OpConstants& constants, const TraceF* const* args, TraceF* result) {
  Op::evaluate(VectorFrame<TraceF>{{&constants}, args, result});
}

template <class Op>
void trace_dual(const OpConstants& constants, const TracedDual* const* args, TracedDual* result) {
  Op::evaluate(DualVectorFrame<TraceF>{{&constants}, args, result});
}

template <class Op>
constexpr TracedOp traced_of() {
  if constexpr (ops::Evaluated<Op, VectorFrame<TraceF>>) return &trace<Op>;
  return nullptr;
}

template <class Op>
constexpr TracedDualOp traced_dual_of() {
  if constexpr (ops::Evaluated<Op, VectorFrame<TraceF>>) return &trace_dual<Op>;
  return nullptr;
}

template <class Op>
struct TracedEntry {
  static constexpr TracedOp value = traced_of<Op>();
};
template <class Op>
struct TracedDualEntry {
  static constexpr TracedDualOp value = traced_dual_of<Op>();
};

constexpr auto traced_ops = op_table<TracedEntry>(TracedOp{nullptr});
constexpr auto traced_dual_ops = op_table<TracedDualEntry>(TracedDualOp{nullptr});

}  // namespace

TracedOp traced_op(OpId op) { return traced_ops[static_cast<std::size_t>(op)]; }
TracedDualOp traced_dual_op(OpId op) { return traced_dual_ops[static_cast<std::size_t>(op)]; }

}  // namespace shadetree
