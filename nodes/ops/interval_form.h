// What both interval backends (interp/interval_program.h and the JIT's
// codegen/emit_interval_program.h) run for an op and a region over a box:
// one definition, so that their enclosures agree to the bit.
#pragma once

#include "nodes/interval_frame.h"
#include "nodes/ops/evaluated.h"
#include "nodes/ops/interval_lengths.h"

namespace shadetree {

template <class Op>
concept OwnIntervalForm = requires(const IntervalFrame& x) { Op::evaluate_interval(x); };

// An op over intervals: its own evaluate_interval where it states one,
// else its generic evaluate instantiated over intervals; then what its
// arguments' lengths say of its result, and its result's length
// (nodes/ops/interval_lengths.h).
template <class Op>
void evaluate_over_intervals(const IntervalFrame& x) {
  if constexpr (OwnIntervalForm<Op>)
    Op::evaluate_interval(x);
  else
    Op::evaluate(x);
  interval_lengths::narrow_by_argument_lengths<Op>(x);
  interval_lengths::record_result_length<Op>(x);
}

// Whether some sample of the box may run a conditional region on
// `condition`: its `then` side (branch 0) where the condition may hold,
// its `else` side where it may fail. A region none may run is passed
// over: the `if` that joins it takes the other side, its condition being
// certain there.
inline bool region_may_run(lanes::Interval condition, int branch) {
  const lanes::IntervalMask mask = frame::loaded(condition);
  return branch == 0 ? mask.may_hold : mask.may_fail;
}

// What a program reports of an output's enclosure: [-inf, +inf] (nothing
// known) where an endpoint is NaN or infinite.
inline lanes::Interval reported_enclosure(lanes::Interval value) {
  return lanes::is_finite(value) ? value : lanes::everything();
}

}  // namespace shadetree
