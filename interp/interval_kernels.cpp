// The interval dispatch (see interval_kernels.h). Instantiating every op
// here is the static check that each has an interval form: an op whose
// generic semantics use a primitive intervals lack (bits, shifts) and
// that states no evaluate_interval does not compile.
#include "interp/interval_kernels.h"

#include "nodes/ops/interval_form.h"
#include "nodes/ops/op_table.h"

namespace shadetree::interp {
namespace {

template <class Op>
constexpr IntervalKernel interval_kernel_of() {
  if constexpr (ops::Evaluated<Op, LaneFrame>) return &evaluate_over_intervals<Op>;
  return nullptr;
}

template <class Op>
struct OpIntervalKernel {
  static constexpr IntervalKernel value = interval_kernel_of<Op>();
};

constexpr auto kernels = op_table<OpIntervalKernel>(IntervalKernel{nullptr});

}  // namespace

IntervalKernel interval_kernel(OpId op) { return kernels[static_cast<std::size_t>(op)]; }

}  // namespace shadetree::interp
