// Interval forms of exp, log, sin and cos (exponential.h, trigonometry.h),
// which compute in bits and so cannot be instantiated over intervals.
// Each lane form is within a few ulp of a function whose monotone pieces
// are known, so the lane form at the endpoints of a piece, widened by more
// than twice that error, encloses the lane form inside it.
//
// They are overloads in the namespace of Interval so that the generic
// semantics calling them (pow, bias, gain, sines, the exp/log/sin/cos ops)
// find them by argument-dependent lookup when instantiated over intervals.
#pragma once

#include <cmath>

#include "nodes/lane_interval.h"
#include "nodes/semantics/exponential.h"
#include "nodes/semantics/trigonometry.h"

namespace shadetree::lanes {

// Relative error bounds, 16 times the documented "about 2 ulp".
inline constexpr float exponential_margin = 4e-6f;
// Below the smallest normal float, ulps are absolute.
inline constexpr float subnormal_margin = 1e-37f;

inline Interval exponential_of(Interval x) {
  if (is_everything(x)) return x;
  const float lo = semantics::exponential_of(x.lo), hi = semantics::exponential_of(x.hi);
  return enclosure(std::max(0.0f, lo - lo * exponential_margin - subnormal_margin),
                   hi + hi * exponential_margin + subnormal_margin);
}

inline Interval logarithm_of(Interval x) {
  if (is_everything(x) || x.lo < 0.0f) return everything();  // log of a negative is NaN
  const float lo = semantics::logarithm_of(x.lo), hi = semantics::logarithm_of(x.hi);
  return enclosure(lo - std::fabs(lo) * exponential_margin - subnormal_margin,
                   hi + std::fabs(hi) * exponential_margin + subnormal_margin);
}

// Below this the reduction keeps the lane forms within a few ulp of sine
// and cosine (trigonometry.h); above it they stay within this bound of
// [-1, 1] (the reduced argument stays under 2, where both polynomials do).
inline constexpr float accurate_trigonometry_limit = 8192.0f;
inline constexpr float trigonometry_margin = 1e-5f;

// sin (phase 0) or cos (phase pi/2, as cos x = sin(x + pi/2)) over x:
// the lane form at the endpoints, and the crests and troughs between.
template <class LaneForm>
Interval sinusoid(Interval x, double phase, LaneForm lane_form) {
  if (!is_finite(x)) return everything();  // sin of an infinity is NaN
  const Interval unit{-1.0f - trigonometry_margin, 1.0f + trigonometry_margin};
  constexpr double pi = 3.14159265358979323846;
  if (std::fabs(x.lo) >= accurate_trigonometry_limit || std::fabs(x.hi) >= accurate_trigonometry_limit ||
      double(x.hi) - double(x.lo) >= 2.0 * pi)
    return unit;
  const float at_lo = lane_form(x.lo), at_hi = lane_form(x.hi);
  Interval result{std::min(at_lo, at_hi), std::max(at_lo, at_hi)};
  // Whether x holds offset + 2 pi k for some whole k.
  auto holds = [&](double offset) {
    const double k = std::ceil((double(x.lo) + phase - offset) / (2.0 * pi));
    return offset + 2.0 * pi * k - phase <= double(x.hi);
  };
  if (holds(pi / 2)) result.hi = 1.0f;
  if (holds(-pi / 2)) result.lo = -1.0f;
  return meet(widened(result, trigonometry_margin), unit);
}

inline Interval sine_of(Interval x) {
  return sinusoid(x, 0.0, [](float v) { return semantics::sine_of(v); });
}

inline Interval cosine_of(Interval x) {
  return sinusoid(x, 3.14159265358979323846 / 2, [](float v) { return semantics::cosine_of(v); });
}

}  // namespace shadetree::lanes
