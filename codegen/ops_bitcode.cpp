// The op library of the JIT, generated from the op list: every op's
// semantics (nodes/ops/) instantiated over clang vector lanes of width 4, 8
// and 16 through a VectorFrame. This file is compiled by clang to LLVM
// bitcode at build time (see CMakeLists.txt), embedded in the shadetree
// binary, linked into every kernel module and inlined there, so the JIT
// computes exactly what the interpreter computes.
//
// One calling convention for every op (ABI-neutral, since vectors are
// never passed by value):
//   void st_<op>_w<W>(F* result, const F* a0, ..., const F* a5,
//                     const OpConstants* constants)
// where each argument and the result point to their declared components
// (an array of 1 to 3 F) and unused arguments are null; and the dual form
// of each op (nodes/dual_frame.h), st_<op>_dual_w<W>, the same with every
// F replaced by a Dual<F> of four F.
#include "nodes/lane_vector.h"
// After the vector primitives, which its templates call.
#include "nodes/dual_frame.h"
#include "nodes/op_id.h"
#include "nodes/ops/evaluated.h"

namespace shadetree {
namespace {

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
#define ST_OP_4(name) ST_OP(name, 4) ST_DUAL_OP(name, 4)
#define ST_OP_8(name) ST_OP(name, 8) ST_DUAL_OP(name, 8)
#define ST_OP_16(name) ST_OP(name, 16) ST_DUAL_OP(name, 16)

SHADETREE_LIBRARY_OPS(ST_OP_4)
SHADETREE_LIBRARY_OPS(ST_OP_8)
SHADETREE_LIBRARY_OPS(ST_OP_16)
