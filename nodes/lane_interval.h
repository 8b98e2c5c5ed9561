// Lane primitives over intervals: F = Interval, I = IntervalInt, M =
// IntervalMask. An op's semantics instantiated with them compute, from a
// box of their arguments, an enclosure of every value the float lanes of
// nodes/lane_scalar.h compute for a point of that box (libfive and
// Keeter's MPR cull implicit surfaces with the same arithmetic).
//
// Why the endpoints are computed in plain float arithmetic: +, -, *, /,
// sqrt and floor are monotone in each argument once rounded to nearest,
// so the rounded results at the endpoints enclose the rounded result at
// every point between; no outward rounding is needed to bound what the
// lane form computes.
//
// NaN: the interval [-inf, +inf] ("everything") also stands for NaN, and
// every primitive returns it wherever a lane could produce NaN (an
// endpoint computed as NaN, sqrt of a negative, division by an interval
// holding 0). Other infinite endpoints are kept: clamping [0, +inf] still
// gives [0, 1].
//
// The primitives that only mean something on bits (to_bits, from_bits,
// &, shifts) are not defined here, so that an op whose semantics use them
// does not compile over intervals and must state its own interval form
// (nodes/ops/, `evaluate_interval`).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "nodes/lane_scalar.h"

namespace shadetree::lanes {

inline constexpr float infinity = std::numeric_limits<float>::infinity();

struct Interval {
  float lo = 0.0f, hi = 0.0f;

  constexpr Interval() = default;
  // A point, implicitly, as the float literals of the semantics are; NaN
  // becomes everything.
  constexpr Interval(float value) : lo(value == value ? value : -infinity), hi(value == value ? value : infinity) {}
  constexpr Interval(float lo, float hi) : lo(lo), hi(hi) {}
};

inline Interval everything() { return {-infinity, infinity}; }
inline bool is_everything(Interval x) { return x.lo == -infinity && x.hi == infinity; }
inline bool is_point(Interval x) { return x.lo == x.hi; }
inline bool is_finite(Interval x) { return std::isfinite(x.lo) && std::isfinite(x.hi); }

// [lo, hi], or everything where an endpoint is NaN.
inline Interval enclosure(float lo, float hi) {
  if (lo != lo || hi != hi) return everything();
  return {lo, hi};
}

// Whether x encloses a value the lane form computed (NaN only by everything).
inline bool encloses(Interval x, float value) {
  if (value != value) return is_everything(x);
  return x.lo <= value && value <= x.hi;
}

inline Interval hull(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }

// Both a and b enclose the same values, so their intersection does.
inline Interval meet(Interval a, Interval b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }

// x widened by `margin` on both sides: for the few ops whose lane form is
// bounded by an approximation error rather than computed endpoint by
// endpoint.
inline Interval widened(Interval x, float margin) {
  if (is_everything(x)) return x;
  return {x.lo - margin, x.hi + margin};
}

inline Interval operator+(Interval a, Interval b) { return enclosure(a.lo + b.lo, a.hi + b.hi); }
inline Interval operator-(Interval a, Interval b) { return enclosure(a.lo - b.hi, a.hi - b.lo); }
inline Interval operator-(Interval a) { return {-a.hi, -a.lo}; }

// Inlined everywhere: the interval forms of noise multiply six times per
// knot, and called, this was an eighth of bounding a volume's empty space.
[[gnu::always_inline]] inline Interval operator*(Interval a, Interval b) {
  const float p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
  if (p0 != p0 || p1 != p1 || p2 != p2 || p3 != p3) return everything();
  return {std::min(std::min(p0, p1), std::min(p2, p3)), std::max(std::max(p0, p1), std::max(p2, p3))};
}

inline Interval operator/(Interval a, Interval b) {
  if (!(b.lo > 0.0f || b.hi < 0.0f)) return everything();  // 0 (or NaN) may divide
  const float q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  for (float v : q)
    if (v != v) return everything();
  return {std::min({q[0], q[1], q[2], q[3]}), std::max({q[0], q[1], q[2], q[3]})};
}

// Whether a comparison may hold for some points of the boxes, and whether
// it may fail for some.
struct IntervalMask {
  bool may_hold = false, may_fail = true;
};

inline constexpr IntervalMask uncertain{true, true};

inline IntervalMask operator<(Interval a, Interval b) {
  if (is_everything(a) || is_everything(b)) return uncertain;  // NaN compares false
  return {a.lo < b.hi, !(a.hi < b.lo)};
}
inline IntervalMask operator<=(Interval a, Interval b) {
  if (is_everything(a) || is_everything(b)) return uncertain;
  return {a.lo <= b.hi, !(a.hi <= b.lo)};
}
inline IntervalMask operator>(Interval a, Interval b) { return b < a; }
inline IntervalMask operator>=(Interval a, Interval b) { return b <= a; }
inline IntervalMask operator==(Interval a, Interval b) {
  if (is_everything(a) || is_everything(b)) return uncertain;
  return {a.lo <= b.hi && b.lo <= a.hi, !(is_point(a) && is_point(b) && a.lo == b.lo)};
}
inline IntervalMask operator!=(Interval a, Interval b) {
  const IntervalMask equal = a == b;
  return {equal.may_fail, equal.may_hold};
}

inline bool any(IntervalMask mask) { return mask.may_hold; }
inline IntervalMask both(IntervalMask a, IntervalMask b) { return {a.may_hold && b.may_hold, a.may_fail || b.may_fail}; }
inline IntervalMask either(IntervalMask a, IntervalMask b) {
  return {a.may_hold || b.may_hold, a.may_fail && b.may_fail};
}
inline IntervalMask negate(IntervalMask a) { return {a.may_fail, a.may_hold}; }
inline IntervalMask differ(IntervalMask a, IntervalMask b) {
  return {(a.may_hold && b.may_fail) || (a.may_fail && b.may_hold),
          (a.may_hold && b.may_hold) || (a.may_fail && b.may_fail)};
}

// a where the mask surely holds, b where it surely fails, else the hull.
inline Interval select(IntervalMask mask, Interval a, Interval b) {
  if (!mask.may_fail) return a;
  if (!mask.may_hold) return b;
  return hull(a, b);
}

inline Interval floor(Interval x) { return {std::floor(x.lo), std::floor(x.hi)}; }

inline Interval abs(Interval x) {
  if (is_everything(x) || x.lo >= 0.0f) return x;
  if (x.hi <= 0.0f) return -x;
  return {0.0f, std::max(-x.lo, x.hi)};
}

// x * x, as the lane form computes it, never below 0.
inline Interval square(Interval x) {
  const Interval magnitude = abs(x);
  if (is_everything(magnitude)) return magnitude;
  return {magnitude.lo * magnitude.lo, magnitude.hi * magnitude.hi};
}

inline Interval sqrt(Interval x) {
  if (is_everything(x) || x.lo < 0.0f) return everything();
  return {std::sqrt(x.lo), std::sqrt(x.hi)};
}

// The lane forms are a < b ? a : b and a > b ? a : b: a NaN in b is
// returned, a NaN in a is not.
inline Interval min(Interval a, Interval b) {
  if (is_everything(b)) return b;
  return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}
inline Interval max(Interval a, Interval b) {
  if (is_everything(b)) return b;
  return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}

// Integers (indices, lattice cells). Their lane forms never overflow in
// the semantics that are instantiated over intervals (indices are clamped
// to their tables first), so neither do these.
struct IntervalInt {
  std::int32_t lo = 0, hi = 0;

  constexpr IntervalInt() = default;
  constexpr IntervalInt(std::int32_t value) : lo(value), hi(value) {}
  constexpr IntervalInt(std::int32_t lo, std::int32_t hi) : lo(lo), hi(hi) {}
};

inline IntervalInt operator+(IntervalInt a, IntervalInt b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline IntervalInt operator-(IntervalInt a, IntervalInt b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline IntervalInt operator*(IntervalInt a, IntervalInt b) {
  const std::int32_t p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
}
inline IntervalMask operator<(IntervalInt a, IntervalInt b) { return {a.lo < b.hi, !(a.hi < b.lo)}; }
inline IntervalMask operator>=(IntervalInt a, IntervalInt b) { return negate(a < b); }

inline IntervalInt select(IntervalMask mask, IntervalInt a, IntervalInt b) {
  if (!mask.may_fail) return a;
  if (!mask.may_hold) return b;
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}
inline IntervalInt min(IntervalInt a, IntervalInt b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }
inline IntervalInt max(IntervalInt a, IntervalInt b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }

// Truncation is monotone; endpoints outside int32 (or NaN) are clamped to
// it, which the lane form never needs.
inline std::int32_t to_int_clamped(float x) {
  if (!(x > -2147483648.0f)) return std::numeric_limits<std::int32_t>::min();
  if (!(x < 2147483648.0f)) return std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(x);
}
inline IntervalInt to_int(Interval x) {
  if (is_everything(x)) return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
  return {to_int_clamped(x.lo), to_int_clamped(x.hi)};
}
inline Interval to_float(IntervalInt i) { return {static_cast<float>(i.lo), static_cast<float>(i.hi)}; }

// The hull of table[index.lo .. index.hi]. The lane form reads only
// indices inside its table, and an index range lies between two of them.
template <class T>
auto table_hull(const T* table, IntervalInt index) {
  T lo = table[index.lo], hi = lo;
  for (std::int32_t i = index.lo + 1; i <= index.hi; ++i) {
    lo = std::min(lo, table[i]);
    hi = std::max(hi, table[i]);
  }
  return std::pair{lo, hi};
}

// Beyond this many entries a float table's hull is not searched (an image
// or a distance grid over a box may span millions): nothing is known.
inline constexpr std::int32_t max_hull_entries = 256;

inline Interval gather(const float* table, IntervalInt index) {
  if (index.hi - index.lo >= max_hull_entries) return everything();
  const auto [lo, hi] = table_hull(table, index);
  return {lo, hi};
}
inline IntervalInt gather(const std::int32_t* table, IntervalInt index) {
  const auto [lo, hi] = table_hull(table, index);
  return {lo, hi};
}
// A 256-entry table: the whole table where the range covers it.
inline Interval gather256(const float* table, IntervalInt index) {
  return gather(table, {std::max(index.lo, 0), std::min(index.hi, 255)});
}
inline IntervalInt gather256(const std::int32_t* table, IntervalInt index) {
  return gather(table, {std::max(index.lo, 0), std::min(index.hi, 255)});
}
inline Interval gather_small(const float* table, std::int32_t, std::int32_t stride, IntervalInt index) {
  return gather(table, index * stride);
}

}  // namespace shadetree::lanes
