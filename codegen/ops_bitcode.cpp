// The op library of the JIT, generated from the op list: every op's
// semantics (nodes/ops/) instantiated over clang vector lanes of width
// SHADETREE_OP_LIBRARY_WIDTH (4, 8 or 16) through a VectorFrame. This file
// is compiled by clang to LLVM bitcode once per width at build time (see
// CMakeLists.txt), embedded in the shadetree binary, linked into every
// kernel module of its width and inlined there, so the JIT computes
// exactly what the interpreter computes.
//
// One calling convention for every op (ABI-neutral, since vectors are
// never passed by value):
//   void st_<op>_w<W>(F* result, const F* a0, ..., const F* a5,
//                     const OpConstants* constants)
// where each argument and the result point to their declared components
// (an array of 1 to 3 F) and unused arguments are null; and the dual form
// of each op (nodes/dual_frame.h), st_<op>_dual_w<W>, the same with every
// F replaced by a Dual<F> of four F.
//
// The library of width 4 also holds each op's interval form (nodes/
// interval_frame.h), which no width changes, for the JIT's interval
// programs (codegen/emit_interval_program.h):
//   void st_<op>_interval(const OpConstants* constants,
//                         const Interval* const* in_planes,
//                         Interval* const* out_planes)
// with IntervalFrame's planes, and the two things such a program does
// besides ops (nodes/ops/interval_form.h): st_interval_region_may_run and
// st_interval_reported.
#include "nodes/lane_vector.h"
#include "nodes/lane_interval.h"
// After the vector and interval primitives, which its templates call.
#include "nodes/dual_frame.h"
#include "nodes/op_id.h"
#include "nodes/ops/evaluated.h"
#include "nodes/ops/interval_form.h"

namespace shadetree {
namespace {

static_assert(SHADETREE_OP_LIBRARY_WIDTH == 4 || SHADETREE_OP_LIBRARY_WIDTH == 8 || SHADETREE_OP_LIBRARY_WIDTH == 16,
              "the op library is built for a vector width of 4, 8 or 16");
static_assert(max_op_args == 6, "the op library's signature below has six argument pointers");

template <class Op, int W>
void evaluate(lanes::floatv<W>* result, const lanes::floatv<W>* const* args, const OpConstants* constants) {
  if constexpr (ops::Evaluated<Op, VectorFrame<lanes::floatv<W>>>)
    Op::evaluate(VectorFrame<lanes::floatv<W>>{{constants}, args, result});
}

template <int W>
using DualV = lanes::Dual<lanes::floatv<W>>;

template <class Op, int W>
void evaluate_dual(DualV<W>* result, const DualV<W>* const* args, const OpConstants* constants) {
  static_assert(sizeof(DualV<W>) == dual_floats * sizeof(lanes::floatv<W>), "a dual is four vectors");
  if constexpr (ops::Evaluated<Op, VectorFrame<lanes::floatv<W>>>)
    Op::evaluate(DualVectorFrame<lanes::floatv<W>>{{constants}, args, result});
}

}  // namespace
}  // namespace shadetree

using namespace shadetree;

#define ST_OP(name, W)                                                                                     \
  extern "C" void st_##name##_w##W(lanes::floatv<W>* result, const lanes::floatv<W>* a0,                 \
                                   const lanes::floatv<W>* a1, const lanes::floatv<W>* a2,               \
                                   const lanes::floatv<W>* a3, const lanes::floatv<W>* a4,               \
                                   const lanes::floatv<W>* a5, const OpConstants* constants) {           \
    const lanes::floatv<W>* args[] = {a0, a1, a2, a3, a4, a5};                                          \
    evaluate<ops::name, W>(result, args, constants);                                                     \
  }
#define ST_DUAL_OP(name, W)                                                                                 \
  extern "C" void st_##name##_dual_w##W(DualV<W>* result, const DualV<W>* a0, const DualV<W>* a1,          \
                                        const DualV<W>* a2, const DualV<W>* a3, const DualV<W>* a4,        \
                                        const DualV<W>* a5, const OpConstants* constants) {                \
    const DualV<W>* args[] = {a0, a1, a2, a3, a4, a5};                                                     \
    evaluate_dual<ops::name, W>(result, args, constants);                                                  \
  }
// W is expanded here, before ST_OP pastes it into names.
#define ST_OP_AT(name, W) ST_OP(name, W) ST_DUAL_OP(name, W)
#define ST_OP_AT_LIBRARY_WIDTH(name) ST_OP_AT(name, SHADETREE_OP_LIBRARY_WIDTH)

SHADETREE_LIBRARY_OPS(ST_OP_AT_LIBRARY_WIDTH)

#if SHADETREE_OP_LIBRARY_WIDTH == 4
#define ST_INTERVAL_OP(name)                                                                                 \
  extern "C" void st_##name##_interval(const OpConstants* constants, const lanes::Interval* const* in_planes, \
                                       lanes::Interval* const* out_planes) {                                 \
    if constexpr (ops::Evaluated<ops::name, LaneFrame>)                                                      \
      evaluate_over_intervals<ops::name>(IntervalFrame{{constants}, in_planes, out_planes});                \
  }
SHADETREE_LIBRARY_OPS(ST_INTERVAL_OP)

extern "C" int st_interval_region_may_run(const lanes::Interval* condition, int branch) {
  return region_may_run(*condition, branch);
}

extern "C" void st_interval_reported(const lanes::Interval* value, lanes::Interval* reported) {
  *reported = reported_enclosure(*value);
}
#endif
