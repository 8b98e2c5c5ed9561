// What an op kernel of the interpreter sees: the planes of its arguments
// and result, its compile-time constants, and the lanes to compute.
#pragma once

#include <cstdint>

#include "nodes/op_frame.h"
#include "nodes/op_id.h"

namespace shadetree::interp {

// The samples of a block an instruction computes: all of them (dense), or
// those listed in `index` (inside a conditional region).
struct Lanes {
  const std::uint16_t* index = nullptr;
  int count = 0;
  bool dense = true;
};

template <class Body>
inline void for_lanes(const Lanes& lanes, Body body) {
  if (lanes.dense) {
    for (int i = 0; i < lanes.count; ++i) body(i);
  } else {
    for (int k = 0; k < lanes.count; ++k) body(static_cast<int>(lanes.index[k]));
  }
}

// One instruction's planes, resolved once per binding: in[3a + c] is
// component c of argument a (a scalar's plane repeated), out[c] of the
// result.
struct InstructionPlanes {
  const float* const* in;
  float* const* out;
  const OpConstants* constants;
};

using OpKernel = void (*)(const InstructionPlanes& planes, const Lanes& lanes);

// The kernel of each library op, generated from the op list (null for ops
// that lowering replaces: inputs and split).
OpKernel op_kernel(OpId op);

}  // namespace shadetree::interp
