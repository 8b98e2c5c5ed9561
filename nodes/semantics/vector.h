// Vector operators over 2 or 3 components, written once over a lane type F.
#pragma once

#include "nodes/lane_scalar.h"
#include "nodes/semantics/vec3.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

template <class F>
Vec3<F> cross(const Vec3<F>& a, const Vec3<F>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// 1 / |v|, or 0 for the zero vector, so normalize(0) = 0 rather than NaN.
template <class F>
F inverse_length_or_zero(F length_squared) {
  F length = sqrt(length_squared);
  return select(length > 0.0f, 1.0f / select(length > 0.0f, length, splat<F>(1.0f)), splat<F>(0.0f));
}

// Inner product of n-component vectors given as arrays of lanes, summed
// in component order from zero.
template <class F>
F dot_n(const F* a, const F* b, int n) {
  F sum = splat<F>(0.0f);
  for (int c = 0; c < n; ++c) sum = sum + a[c] * b[c];
  return sum;
}

// dot_n(v, v, n), through square so that an interval lane keeps it >= 0.
template <class F>
F sum_of_squares_n(const F* v, int n) {
  F sum = splat<F>(0.0f);
  for (int c = 0; c < n; ++c) sum = sum + square(v[c]);
  return sum;
}

template <class F>
F length_n(const F* v, int n) {
  return sqrt(sum_of_squares_n(v, n));
}

// v / |v|, 0 for the zero vector. Where v's squares underflow (|v| below
// about 2^-63), v is first scaled by 2^126, exactly: their sum, rounded to
// a multiple of 2^-149 or to 0, would have made the result up to sqrt(1.5)
// long, or 0 for a vector that is not. So the result is a unit vector to
// rounding, which interval forms rely on (nodes/ops/interval_lengths.h).
template <class F>
void normalize_n(const F* v, int n, F* out) {
  const F squares = sum_of_squares_n(v, n);
  const auto tiny = squares < 0x1p-126f;
  const F scale = select(tiny, splat<F>(0x1p126f), splat<F>(1.0f));
  F scaled[3];
  for (int c = 0; c < n; ++c) scaled[c] = v[c] * scale;
  F inverse = inverse_length_or_zero(select(tiny, sum_of_squares_n(scaled, n), squares));
  for (int c = 0; c < n; ++c) out[c] = scaled[c] * inverse;
}

}  // namespace shadetree::semantics
