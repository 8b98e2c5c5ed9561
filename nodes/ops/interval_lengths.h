// Bounds on vectors' lengths in interval programs (nodes/interval_frame.h:
// a value's fourth plane). A box of components forgets how they vary
// together: over a box near the unit sphere d / |d| has every component in
// [-1, 1], so k d / |d| reaches sqrt(3) k from 0 at the box's corners,
// while its length is at most k. The shape transfer function volumes push
// x along such a direction (Gilet & Dischler 2010, formula 3), and their
// boxes' enclosures found a shell of radius 0.7 + sqrt(3) 0.22 occupied
// where the density is 0 beyond 0.7 + 0.22.
//
// A vector result whose length some op reads (ir/interval_lengths_read.h)
// gets the length its op implies from its arguments' (normalize at most
// 1, a product at most the product of a length and the other argument's
// largest component, a sum or difference within the triangle inequality),
// met with what its components say; its components are then met with
// that length. length, dot and sphere read their arguments' lengths. The rules bound the exact length of the float
// vector the lanes hold, widened by what rounding moves a length or a sum
// of squares computed in float (a few ulp), and by underflow and overflow
// of the squares.
#pragma once

#include <algorithm>
#include <type_traits>

#include "nodes/interval_frame.h"
#include "nodes/ops/evaluated.h"
#include "nodes/semantics/shape_intervals.h"
#include "nodes/semantics/soft_objects.h"
#include "nodes/semantics/vector.h"

namespace shadetree::interval_lengths {

using lanes::Interval;

// A length, or a squared length, computed in float, widened to enclose
// both the exact value and what the lanes' float arithmetic makes of it:
// within a relative 1e-5 (some ulps) where the squares of a length neither
// underflow nor overflow; beyond that, anything from 0 below 1e-18 and up
// to infinity above 1e18. A NaN endpoint leaves only that a length is not
// negative.
inline Interval as_computed(Interval computed) {
  if (computed.lo != computed.lo || computed.hi != computed.hi) return {0.0f, lanes::infinity};
  constexpr float tiny = 1e-18f, huge = 1e18f;
  const float lo = computed.lo < tiny ? 0.0f : computed.lo > huge ? huge : computed.lo * (1.0f - 1e-5f);
  const float hi = computed.hi > huge ? lanes::infinity : computed.hi * (1.0f + 1e-5f) + 1e-30f;
  return {lo, hi};
}

// What a vector's components say of its length.
inline Interval length_of_components(const Interval* v, int n) {
  return as_computed(lanes::sqrt(semantics::sum_of_squares_n(v, n)));
}

// Argument a's length: its plane's bound, which the op that made it met
// with its components' already, or else its components'.
inline Interval argument_length(const IntervalFrame& x, int a) {
  if (!lanes::is_everything(x.in_length(a))) return x.in_length(a);
  Interval v[3];
  frame::to_array(x, a, v);
  return length_of_components(v, x.arg_components(a));
}

// The smallest and the largest magnitude of argument a's components.
inline Interval component_magnitudes(const IntervalFrame& x, int a) {
  Interval result = lanes::abs(x.in(a, 0));
  for (int c = 1; c < x.arg_components(a); ++c) {
    const Interval magnitude = lanes::abs(x.in(a, c));
    result = {std::min(result.lo, magnitude.lo), std::max(result.hi, magnitude.hi)};
  }
  return result;
}

// |a - b| and |a + b| lie within |a| -/+ |b|.
inline Interval triangle(Interval a, Interval b) {
  return as_computed({std::max({0.0f, a.lo - b.hi, b.lo - a.hi}), a.hi + b.hi});
}

// The ops whose result's length follows from their arguments' more
// tightly than from the result's components.
template <class Op>
inline constexpr bool has_length_rule = std::is_same_v<Op, ops::normalize> || std::is_same_v<Op, ops::neg> ||
                                        std::is_same_v<Op, ops::mul> || std::is_same_v<Op, ops::add> ||
                                        std::is_same_v<Op, ops::sub>;

// The length op `Op` gives its vector result, from its arguments.
template <class Op>
Interval result_length(const IntervalFrame& x) {
  constexpr int arity = std::is_same_v<Op, ops::normalize> || std::is_same_v<Op, ops::neg> ? 1 : 2;
  if (!x.finite_inputs(arity)) return lanes::everything();
  if constexpr (std::is_same_v<Op, ops::normalize>) {
    return {0.0f, lanes::unit_length_bound};
  } else if constexpr (std::is_same_v<Op, ops::neg>) {
    return argument_length(x, 0);
  } else if constexpr (std::is_same_v<Op, ops::mul>) {
    // |a * b| (per component) is within |a| times b's smallest and largest
    // component magnitudes, and the other way round; a scalar read as a
    // vector has one magnitude, its own.
    const Interval a = argument_length(x, 0), b = argument_length(x, 1);
    const Interval a_parts = component_magnitudes(x, 0), b_parts = component_magnitudes(x, 1);
    return lanes::meet(as_computed({a.lo * b_parts.lo, a.hi * b_parts.hi}),
                       as_computed({b.lo * a_parts.lo, b.hi * a_parts.hi}));
  } else {
    return triangle(argument_length(x, 0), argument_length(x, 1));
  }
}

// A vector result's length, where a rule gives it and an op reads it
// (x.keeps_length()), and its components met with it. Elsewhere its plane
// keeps saying nothing: a reader takes the length from the components
// (argument_length), which is all such a plane would have held.
template <class Op>
void record_result_length(const IntervalFrame& x) {
  if constexpr (has_length_rule<Op>) {
    if (!x.keeps_length() || x.components() < 2) return;
    Interval v[3];
    frame::for_components(x.components(), [&](int c) { v[c] = x.out(c); });
    const Interval length = lanes::meet(result_length<Op>(x), length_of_components(v, x.components()));
    x.out_length() = length;
    frame::for_components(x.components(), [&](int c) { x.out(c) = lanes::meet(x.out(c), {-length.hi, length.hi}); });
  }
}

// A scalar result that depends on an argument's length, met with what
// that length says of it.
template <class Op>
void narrow_by_argument_lengths(const IntervalFrame& x) {
  if constexpr (std::is_same_v<Op, ops::length>) {
    if (x.arg_components(0) >= 2 && x.finite_inputs(1)) x.out() = lanes::meet(x.out(), argument_length(x, 0));
  } else if constexpr (std::is_same_v<Op, ops::dot>) {
    // Cauchy-Schwarz.
    if (x.arg_components(0) >= 2 && x.finite_inputs(2)) {
      const Interval reach = as_computed(argument_length(x, 0) * argument_length(x, 1));
      x.out() = lanes::meet(x.out(), {-reach.hi, reach.hi});
    }
  } else if constexpr (std::is_same_v<Op, ops::sphere>) {
    // The squared distance from the centre, from the length of p - center.
    if (x.finite_inputs(4)) {
      const Interval distance = triangle(argument_length(x, 0), argument_length(x, 1));
      const Interval squared = as_computed(lanes::square(distance));
      x.out() = lanes::meet(x.out(), semantics::soft_sphere_at(squared, x.in(2), x.in(3)));
    }
  }
}

}  // namespace shadetree::interval_lengths
