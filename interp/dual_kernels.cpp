// The dual dispatch (see dual_kernels.h). Instantiating every op here is
// the static check that each has a dual form: an op whose generic
// semantics compute in bits does not compile over duals until its
// derivative is stated (nodes/semantics/transcendental_duals.h).
#include "interp/dual_kernels.h"

#include "nodes/ops/op_table.h"
#include "nodes/dual_frame.h"
#include "nodes/ops/evaluated.h"

namespace shadetree::interp {
namespace {

template <class Op>
void run_dual(const InstructionPlanes& planes, const Lanes& lanes) {
  lanes::Dual<float> result[3];
  DualLaneFrame x{{planes.constants}, planes.in, planes.out, 0, result};
  const int components = planes.constants->components;
  for_lanes(lanes, [&](int lane) {
    x.lane = lane;
    Op::evaluate(x);
    for (int c = 0; c < components; ++c) {
      float* const* out = planes.out + dual_floats * c;
      out[0][lane] = result[c].value;
      out[1][lane] = result[c].dx;
      out[2][lane] = result[c].dy;
      out[3][lane] = result[c].dz;
    }
  });
}

template <class Op>
constexpr OpKernel dual_kernel_of() {
  if constexpr (ops::Evaluated<Op, LaneFrame>) return &run_dual<Op>;
  return nullptr;
}

template <class Op>
struct OpDualKernel {
  static constexpr OpKernel value = dual_kernel_of<Op>();
};

constexpr auto kernels = op_table<OpDualKernel>(OpKernel{nullptr});

}  // namespace

OpKernel dual_op_kernel(OpId op) { return kernels[static_cast<std::size_t>(op)]; }

}  // namespace shadetree::interp
