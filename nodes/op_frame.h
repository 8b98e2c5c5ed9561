// The op ABI: what an op's semantics see, the same in every backend.
//
// An op is evaluated through a frame X that gives it
//   x.in(a, c)   component c of argument a, as a lane value F (arguments
//                always have their declared component count: a scalar
//                passed for a vector is read splatted),
//   x.out(c)     a reference to component c of the result,
// and the constants its instruction fixed at compile time (OpConstants):
// attribute data, immediates, noise tables and component counts. The
// interpreter's LaneFrame holds planes of floats and one lane index; the
// JIT's VectorFrame holds arrays of clang vector lanes. An op's semantics
// are one `template <class X> static void evaluate(const X& x)` in
// nodes/ops/, compiled once for each frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "nodes/lane_scalar.h"
#include "nodes/limits.h"
#include "nodes/noise_tables.h"
#include "nodes/semantics/vec3.h"

namespace shadetree {

// What an instruction fixes at compile time, besides its arguments. The
// JIT builds it as a constant LLVM struct of the same layout (see
// codegen/emit_kernel.cpp), so its loads fold away after inlining.
struct OpConstants {
  const float* data = nullptr;          // attribute data: knots, table entries
  const NoiseTables* tables = nullptr;  // for ops that read the noise tables
  std::int32_t data_count = 0;
  std::int32_t immediate[2] = {0, 0};
  std::int32_t components = 1;                    // of the result
  std::int32_t arg_components[max_op_args] = {};  // declared, per argument
};
static_assert(sizeof(OpConstants) == 56 && offsetof(OpConstants, data_count) == 16 &&
                  offsetof(OpConstants, components) == 28 && offsetof(OpConstants, arg_components) == 32,
              "codegen/emit_kernel.cpp builds OpConstants with this layout");

// The accessors every frame shares.
struct FrameConstants {
  const OpConstants* constants;

  int components() const { return constants->components; }
  int arg_components(int a) const { return constants->arg_components[a]; }
  const float* data() const { return constants->data; }
  int data_count() const { return constants->data_count; }
  int immediate(int i) const { return constants->immediate[i]; }
  const NoiseTables& tables() const { return *constants->tables; }
};

// One sample of the interpreter: in_planes[3a + c] is component c of
// argument a (a scalar's one plane repeated), out_planes[c] of the result.
struct LaneFrame : FrameConstants {
  using Lane = float;
  const float* const* in_planes;
  float* const* out_planes;
  int lane;

  float in(int a, int c = 0) const { return in_planes[3 * a + c][lane]; }
  float& out(int c = 0) const { return out_planes[c][lane]; }
};

// W samples of the JIT: args[a] points to the declared components of
// argument a, result to those of the result.
template <class F>
struct VectorFrame : FrameConstants {
  using Lane = F;
  const F* const* args;
  F* result;

  F in(int a, int c = 0) const { return args[a][c]; }
  F& out(int c = 0) const { return result[c]; }
};

template <class X>
using LaneOf = typename X::Lane;

// Helpers for writing semantics over frames.
namespace frame {

// body(c) for each of `count` (1 to 3) components. Not a loop: the op
// library is optimized by clang before a kernel fixes `count`, and a loop
// over an unknown count leaves loop structure that the kernel's optimizer
// does not entirely undo once the count is a constant; guarded calls fold
// to straight-line code.
template <class Body>
void for_components(int count, Body body) {
  body(0);
  if (count > 1) body(1);
  if (count > 2) body(2);
}

// out[c] = f(in(0, c), ..., in(Arity - 1, c)) for one component.
template <class X, class Function, int... A>
void apply_to_component(const X& x, Function& f, int c, std::integer_sequence<int, A...>) {
  x.out(c) = f(x.in(A, c)...);
}

// The same for each result component.
template <int Arity, class X, class Function>
void componentwise(const X& x, Function f) {
  for_components(x.components(), [&](int c) { apply_to_component(x, f, c, std::make_integer_sequence<int, Arity>{}); });
}

template <class X>
semantics::Vec3<LaneOf<X>> vec3(const X& x, int a) {
  return {x.in(a, 0), x.in(a, 1), x.in(a, 2)};
}

template <class X>
void store_vec3(const X& x, const semantics::Vec3<LaneOf<X>>& value) {
  x.out(0) = value.x;
  x.out(1) = value.y;
  x.out(2) = value.z;
}

// Bools are stored as 0 / 1 in float lanes.
template <class F, class Mask>
F stored(Mask mask) {
  return lanes::select(mask, lanes::splat<F>(1.0f), lanes::splat<F>(0.0f));
}
template <class F>
auto loaded(F value) {
  return value != 0.0f;
}

// Argument a as an array of its declared components.
template <class X>
void to_array(const X& x, int a, LaneOf<X> (&out)[3]) {
  for_components(x.arg_components(a), [&](int c) { out[c] = x.in(a, c); });
}

}  // namespace frame
}  // namespace shadetree
