// Componentwise operators, written once over a lane type F. Vector-typed
// nodes apply these to each component.
#pragma once

#include "nodes/lane_scalar.h"
#include "nodes/semantics/exponential.h"
#include "nodes/semantics/trigonometry.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

template <class F> F add(F a, F b) { return a + b; }
template <class F> F sub(F a, F b) { return a - b; }
template <class F> F mul(F a, F b) { return a * b; }
template <class F> F div(F a, F b) { return a / b; }
template <class F> F neg(F x) { return -x; }
template <class F> F minimum(F a, F b) { return min(a, b); }
template <class F> F maximum(F a, F b) { return max(a, b); }
template <class F> F clamp(F x, F lo, F hi) { return min(max(x, lo), hi); }
template <class F> F absolute(F x) { return abs(x); }
template <class F> F floor_of(F x) { return floor(x); }
template <class F> F fract(F x) { return x - floor(x); }
template <class F> F mod(F a, F b) { return a - b * floor(a / b); }
template <class F> F power(F a, F b) { return power_of(a, b); }
template <class F> F square_root(F x) { return sqrt(x); }
template <class F> F exponential(F x) { return exponential_of(x); }
template <class F> F logarithm(F x) { return logarithm_of(x); }
template <class F> F sine(F x) { return sine_of(x); }
template <class F> F cosine(F x) { return cosine_of(x); }
template <class F> F mix(F a, F b, F t) { return a + (b - a) * t; }
template <class F> F step(F edge, F x) { return select(x < edge, splat<F>(0.0f), splat<F>(1.0f)); }

template <class F>
F smoothstep(F edge0, F edge1, F x) {
  F t = clamp((x - edge0) / (edge1 - edge0), splat<F>(0.0f), splat<F>(1.0f));
  return t * t * (3.0f - t * 2.0f);
}

// Perlin & Hoffert 1989 section 2.3: bias_b(t) = t^(ln b / ln 1/2), a power
// curve through (0,0), (1/2,b), (1,1). t is clamped to the unit interval
// and b to its inside, where the curve is defined.
template <class F>
F bias(F t, F b) {
  t = clamp(t, splat<F>(0.0f), splat<F>(1.0f));
  b = clamp(b, splat<F>(1e-6f), splat<F>(1.0f - 1e-6f));
  return power_of(t, logarithm_of(b) / logarithm_of(splat<F>(0.5f)));
}

// 1989 section 2.3: gain as a spline of two bias curves,
// t < 1/2 ? bias_{1-g}(2t) / 2 : 1 - bias_{1-g}(2 - 2t) / 2.
template <class F>
F gain(F t, F g) {
  auto lower_half = t < 0.5f;
  F curve = bias(select(lower_half, t * 2.0f, 2.0f - t * 2.0f), 1.0f - g) * 0.5f;
  return select(lower_half, curve, 1.0f - curve);
}

template <class F>
F remap(F x, F from_lo, F from_hi, F to_lo, F to_hi) {
  return to_lo + (x - from_lo) * (to_hi - to_lo) / (from_hi - from_lo);
}

// Comparisons and logic: masks in, masks out. Storage of bools (0 or 1) is
// the backend's business.
template <class F> auto less(F a, F b) { return a < b; }
template <class F> auto less_equal(F a, F b) { return a <= b; }
template <class F> auto greater(F a, F b) { return a > b; }
template <class F> auto greater_equal(F a, F b) { return a >= b; }
template <class F> auto equal(F a, F b) { return a == b; }
template <class F> auto not_equal(F a, F b) { return a != b; }

}  // namespace shadetree::semantics
