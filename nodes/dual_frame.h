// The op ABI over dual numbers (see nodes/op_frame.h): frames whose lanes
// are duals (nodes/lane_dual.h), so that an op's generic `evaluate`
// computes its value and its gradient with respect to P. A dual value of k
// components is stored as 4k floats, component by component: value,
// d/dP.x, d/dP.y, d/dP.z. Arguments that do not depend on P are read with
// zero partials.
//
// Including this header brings every dual form in: the lane primitives and
// the overloads of the semantic functions that compute in bits.
#pragma once

#include "nodes/lane_dual.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/transcendental_duals.h"

namespace shadetree {

// Floats per component of a dual value.
inline constexpr int dual_floats = 4;

// One sample of the interpreter: in_planes[12a + 4c + k] is part k of
// component c of argument a (planes of zeros for the partials of a value
// that does not depend on P), out_planes[4c + k] of the result.
struct DualLaneFrame : FrameConstants {
  using Lane = lanes::Dual<float>;
  const float* const* in_planes;
  float* const* out_planes;
  int lane;
  Lane* result;  // the op writes here; the interpreter stores it to out_planes

  Lane in(int a, int c = 0) const {
    const float* const* parts = in_planes + dual_floats * (3 * a + c);
    return {parts[0][lane], parts[1][lane], parts[2][lane], parts[3][lane]};
  }
  Lane& out(int c = 0) const { return result[c]; }
};

// W samples of the JIT: args[a] points to the declared components of
// argument a as duals, result to those of the result.
template <class F>
struct DualVectorFrame : FrameConstants {
  using Lane = lanes::Dual<F>;
  const Lane* const* args;
  Lane* result;

  Lane in(int a, int c = 0) const { return args[a][c]; }
  Lane& out(int c = 0) const { return result[c]; }
};

}  // namespace shadetree
