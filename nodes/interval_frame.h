// The op ABI over intervals (see nodes/op_frame.h): a frame whose lanes
// are intervals, one per component of each argument and of the result.
// Through it an op's generic `evaluate` computes an enclosure of its lane
// form over a box of its arguments (nodes/lane_interval.h); an op for
// which that cannot be right states its own `evaluate_interval`.
//
// Including this header brings every interval form in: the lane
// primitives and the overloads of the semantic functions that compute in
// bits, which the generic semantics reach by argument-dependent lookup.
#pragma once

#include "nodes/lane_interval.h"
#include "nodes/op_frame.h"
#include "nodes/semantics/noise_intervals.h"
#include "nodes/semantics/transcendental_intervals.h"

namespace shadetree {

// in_planes[4a + c] is component c of argument a (a scalar's one
// interval repeated) and in_planes[4a + 3] what is known of its length,
// out_planes[c] of the result and out_planes[3] its length, or null (see
// interval_planes_per_value, nodes/limits.h).
struct IntervalFrame : FrameConstants {
  using Lane = lanes::Interval;
  const lanes::Interval* const* in_planes;
  lanes::Interval* const* out_planes;

  lanes::Interval in(int a, int c = 0) const { return *in_planes[interval_planes_per_value * a + c]; }
  lanes::Interval& out(int c = 0) const { return *out_planes[c]; }
  // Bounds on the Euclidean length of a vector argument and of a vector
  // result (nodes/ops/interval_lengths.h): an argument's is everything
  // where none is known, and a result's is kept only where some op reads
  // it (ir/interval_lengths_read.h; out_planes[3] is null elsewhere).
  lanes::Interval in_length(int a) const { return *in_planes[interval_planes_per_value * a + 3]; }
  bool keeps_length() const { return out_planes[3] != nullptr; }
  lanes::Interval& out_length() const { return *out_planes[3]; }

  // Whether every component of the first `args` arguments is finite.
  bool finite_inputs(int args) const {
    for (int a = 0; a < args; ++a)
      for (int c = 0; c < arg_components(a); ++c)
        if (!lanes::is_finite(in(a, c))) return false;
    return true;
  }
};

}  // namespace shadetree
