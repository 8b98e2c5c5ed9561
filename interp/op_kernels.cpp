// The interpreter's op dispatch, generated from the op list: each op's
// semantics (nodes/ops/) evaluated lane by lane through a LaneFrame.
#include <utility>

#include "interp/exec_context.h"
#include "nodes/ops/op_table.h"
#include "nodes/ops/evaluated.h"

namespace shadetree::interp {
namespace {

// Componentwise ops loop over components, then lanes, so that the inner
// loop is a tight loop over planes (which the compiler vectorizes).
template <class Op, int... A>
void run_componentwise(const InstructionPlanes& planes, const Lanes& lanes, std::integer_sequence<int, A...>) {
  for (int c = 0; c < planes.constants->components; ++c) {
    float* out = planes.out[c];
    const float* in[] = {planes.in[3 * A + c]...};
    for_lanes(lanes, [&](int lane) { out[lane] = Op::apply(in[A][lane]...); });
  }
}

template <class Op>
void run_op(const InstructionPlanes& planes, const Lanes& lanes) {
  if constexpr (requires { Op::arity; }) {
    run_componentwise<Op>(planes, lanes, std::make_integer_sequence<int, Op::arity>{});
  } else {
    LaneFrame x{{planes.constants}, planes.in, planes.out, 0};
    for_lanes(lanes, [&](int lane) {
      x.lane = lane;
      Op::evaluate(x);
    });
  }
}

template <class Op>
constexpr OpKernel kernel_of() {
  if constexpr (ops::Evaluated<Op, LaneFrame>) return &run_op<Op>;
  return nullptr;
}

template <class Op>
struct LaneKernel {
  static constexpr OpKernel value = kernel_of<Op>();
};

constexpr auto kernels = op_table<LaneKernel>(OpKernel{nullptr});

}  // namespace

OpKernel op_kernel(OpId op) { return kernels[static_cast<std::size_t>(op)]; }

}  // namespace shadetree::interp
