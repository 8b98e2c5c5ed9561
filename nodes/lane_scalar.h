// Lane primitives for one sample at a time: F = float, I = int32_t, M = bool.
//
// Node semantics (nodes/semantics/) are written once, as templates over a
// lane type F, using only these primitives: arithmetic, compares, select,
// floor, gather from a table, and any() for loops with a per-lane trip
// count. The interpreter instantiates them with F = float. A vector backend
// declares the same names for its vector types before including the
// semantics, so both compute the same operations in the same order.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace shadetree::lanes {

inline float select(bool mask, float a, float b) { return mask ? a : b; }
inline std::int32_t select(bool mask, std::int32_t a, std::int32_t b) { return mask ? a : b; }
inline bool any(bool mask) { return mask; }
inline bool both(bool a, bool b) { return a && b; }
inline bool either(bool a, bool b) { return a || b; }
inline bool negate(bool a) { return !a; }
inline bool differ(bool a, bool b) { return a != b; }

// visit(0) then visit(1), as integral constants: a loop of two written
// out whatever a compiler's unrolling makes of its body (each call is an
// instantiation of its own, called once).
template <class Visit>
void each_of_0_and_1(Visit visit) {
  visit(std::integral_constant<int, 0>{});
  visit(std::integral_constant<int, 1>{});
}

// x * x, named so that an interval lane can bound it below by 0.
template <class F>
F square(F x) {
  return x * x;
}

inline float floor(float x) { return std::floor(x); }
inline float abs(float x) { return std::fabs(x); }
inline float sqrt(float x) { return std::sqrt(x); }
inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
inline std::int32_t min(std::int32_t a, std::int32_t b) { return a < b ? a : b; }
inline std::int32_t max(std::int32_t a, std::int32_t b) { return a > b ? a : b; }

// x must already be integral and within int32 range.
inline std::int32_t to_int(float x) { return static_cast<std::int32_t>(x); }
inline float to_float(std::int32_t i) { return static_cast<float>(i); }

// The bits of an IEEE float and back, for exponent arithmetic.
// (memcpy, not std::bit_cast: emit --cpp's output is C++17.)
inline std::int32_t to_bits(float x) {
  std::int32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}
inline float from_bits(std::int32_t bits) {
  float x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

inline float gather(const float* table, std::int32_t index) { return table[index]; }
inline std::int32_t gather(const std::int32_t* table, std::int32_t index) { return table[index]; }
// Lookups in a table of 256 entries (the noise tables, which keep entry 0
// once more after them) with index in [0, 256): a vector backend may hold
// such a table in registers.
inline float gather256(const float* table, std::int32_t index) { return table[index]; }
inline std::int32_t gather256(const std::int32_t* table, std::int32_t index) { return table[index]; }
// A noise table's entries at index and index + 1 mod 256, index in
// [0, 256): the table holds 256 entries and the first once more
// (nodes/noise_tables.h), so a vector backend reads both as one 64-bit
// lookup per lane.
template <class T>
std::array<T, 2> gather256_pair(const T* table, std::int32_t index) {
  return {table[index], table[index + 1]};
}
// Entry `index` of a float table of `count` entries `stride` floats apart
// (one component of a spline's knots), index in [0, count): a vector
// backend may hold a small one in registers.
inline float gather_small(const float* table, std::int32_t, std::int32_t stride, std::int32_t index) {
  return table[index * stride];
}

template <class F>
using IntOf = decltype(to_int(F{}));
template <class F>
using MaskOf = decltype(F{} < F{});

template <class F>
F splat(float value) {
  return F{} + value;
}

// A loop whose trip count differs per lane, at most `cap` steps: step i
// runs while condition(i, state...), the mask of the lanes still going
// (i as a lane of the type of the first state), holds for some lane, as
// step(mask, state...). Lanes out of the mask must leave the state as it
// is (through select), so running a step for none of them is harmless.
// The GLSL tracer (nodes/lane_trace.h) writes it as one rolled loop.
template <class Condition, class Step, class First, class... Rest>
void loop_while(int cap, Condition condition, Step step, First& first, Rest&... rest) {
  for (int i = 0; i < cap; ++i) {
    const First index = splat<First>(float(i));
    const auto active = condition(index, first, rest...);
    if (!any(active)) break;
    step(active, first, rest...);
  }
}

}  // namespace shadetree::lanes
