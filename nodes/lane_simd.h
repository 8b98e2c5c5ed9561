// Lane primitives for the C++ that `shadetree emit --cpp` writes: W samples
// at a time in GCC/clang vector types (vector_size, which both compilers
// take, unlike clang's ext_vector_type), F = floatv, I = intv, M = intv
// (all ones / zero per lane). W is fixed by the target the emitted code is
// compiled for: 16 with AVX-512, 8 with AVX, 4 with SSE2 or NEON, and no
// vector type at all (the scalar lanes of lane_scalar.h only) without them
// or with SHADETREE_NO_SIMD defined. Each primitive does per lane what its
// scalar twin does, so the semantics compute the same values either way.
// Emitted with the semantics, before them; never compiled into shadetree.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#if !defined(SHADETREE_NO_SIMD) && (defined(__GNUC__) || defined(__clang__))
#if defined(__AVX512F__)
#define SHADETREE_SIMD_WIDTH 16
#elif defined(__AVX__)
#define SHADETREE_SIMD_WIDTH 8
#elif defined(__SSE2__) || defined(__ARM_NEON)
#define SHADETREE_SIMD_WIDTH 4
#endif
#endif
#if defined(__SSE4_1__) || defined(__AVX__) || defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace shadetree::lanes {

// One sample's lanes: loads and stores of plain floats.
template <class F>
F load(const float* from) {
  F value;
  std::memcpy(&value, from, sizeof value);
  return value;
}
template <class F>
void store(float* to, F value) {
  std::memcpy(to, &value, sizeof value);
}

#ifdef SHADETREE_SIMD_WIDTH
inline constexpr int simd_width = SHADETREE_SIMD_WIDTH;
typedef float floatv __attribute__((vector_size(4 * SHADETREE_SIMD_WIDTH)));
typedef std::int32_t intv __attribute__((vector_size(4 * SHADETREE_SIMD_WIDTH)));

inline floatv select(intv mask, floatv a, floatv b) { return mask ? a : b; }
inline intv select(intv mask, intv a, intv b) { return mask ? a : b; }
inline bool any(intv mask) {
  for (int i = 0; i < simd_width; ++i)
    if (mask[i]) return true;
  return false;
}
inline intv both(intv a, intv b) { return a & b; }
inline intv either(intv a, intv b) { return a | b; }
inline intv negate(intv a) { return ~a; }
inline intv differ(intv a, intv b) { return a ^ b; }

inline intv to_bits(floatv x) { return (intv)x; }
inline floatv from_bits(intv bits) { return (floatv)bits; }
inline intv to_int(floatv x) { return __builtin_convertvector(x, intv); }
inline floatv to_float(intv i) { return __builtin_convertvector(i, floatv); }

inline floatv abs(floatv x) { return from_bits(to_bits(x) & 0x7fffffff); }
inline floatv min(floatv a, floatv b) { return a < b ? a : b; }
inline floatv max(floatv a, floatv b) { return a > b ? a : b; }
inline intv min(intv a, intv b) { return a < b ? a : b; }
inline intv max(intv a, intv b) { return a > b ? a : b; }

inline floatv floor(floatv x) {
#if defined(__AVX512F__) && SHADETREE_SIMD_WIDTH == 16
  return (floatv)_mm512_roundscale_ps((__m512)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
#elif defined(__AVX__) && SHADETREE_SIMD_WIDTH == 8
  return (floatv)_mm256_floor_ps((__m256)x);
#elif defined(__SSE4_1__) && SHADETREE_SIMD_WIDTH == 4
  return (floatv)_mm_floor_ps((__m128)x);
#else
  // Floats of magnitude 2^23 and more (and NaN) are their own floor; the
  // others truncate exactly through int32, then step down where negative.
  const intv small = abs(x) < 8388608.0f;
  const floatv truncated = to_float(to_int(select(small, x, floatv{} + 0.0f)));
  const floatv stepped = truncated - select(truncated > x, floatv{} + 1.0f, floatv{} + 0.0f);
  return select(small, stepped, x);
#endif
}

inline floatv sqrt(floatv x) {
#if defined(__AVX512F__) && SHADETREE_SIMD_WIDTH == 16
  return (floatv)_mm512_sqrt_ps((__m512)x);
#elif defined(__AVX__) && SHADETREE_SIMD_WIDTH == 8
  return (floatv)_mm256_sqrt_ps((__m256)x);
#elif defined(__SSE4_1__) && SHADETREE_SIMD_WIDTH == 4
  return (floatv)_mm_sqrt_ps((__m128)x);
#else
  floatv result;
  for (int i = 0; i < simd_width; ++i) result[i] = std::sqrt(x[i]);
  return result;
#endif
}

// Table lookups, one load per lane (or the target's gather).
inline floatv gather(const float* table, intv index) {
#if defined(__AVX512F__) && SHADETREE_SIMD_WIDTH == 16
  return (floatv)_mm512_i32gather_ps((__m512i)index, table, 4);
#elif defined(__AVX2__) && SHADETREE_SIMD_WIDTH == 8
  return (floatv)_mm256_i32gather_ps(table, (__m256i)index, 4);
#else
  floatv result;
  for (int i = 0; i < simd_width; ++i) result[i] = table[index[i]];
  return result;
#endif
}
inline intv gather(const std::int32_t* table, intv index) {
#if defined(__AVX512F__) && SHADETREE_SIMD_WIDTH == 16
  return (intv)_mm512_i32gather_epi32((__m512i)index, table, 4);
#elif defined(__AVX2__) && SHADETREE_SIMD_WIDTH == 8
  return (intv)_mm256_i32gather_epi32(reinterpret_cast<const int*>(table), (__m256i)index, 4);
#else
  intv result;
  for (int i = 0; i < simd_width; ++i) result[i] = table[index[i]];
  return result;
#endif
}
inline floatv gather256(const float* table, intv index) { return gather(table, index); }
inline intv gather256(const std::int32_t* table, intv index) { return gather(table, index); }
// A noise table's entries at index and index + 1 (the tables keep entry 0
// again after the last): with AVX-512, one 64-bit gather per lane split
// into its halves, half the gathered elements of two 32-bit gathers.
template <class T>
auto gather256_pair(const T* table, intv index) {
  using Lanes = decltype(gather(table, index));
#if defined(__AVX512F__) && SHADETREE_SIMD_WIDTH == 16
  const __m512i low = _mm512_i32gather_epi64(_mm512_castsi512_si256((__m512i)index), table, 4);
  const __m512i high = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64((__m512i)index, 1), table, 4);
  const __m512i firsts = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  const __m512i seconds = _mm512_add_epi32(firsts, _mm512_set1_epi32(1));
  return std::array<Lanes, 2>{(Lanes)_mm512_permutex2var_epi32(low, firsts, high),
                              (Lanes)_mm512_permutex2var_epi32(low, seconds, high)};
#else
  return std::array<Lanes, 2>{gather(table, index), gather(table, index + 1)};
#endif
}
inline floatv gather_small(const float* table, std::int32_t, std::int32_t stride, intv index) {
  return gather(table, index * stride);
}
#endif

}  // namespace shadetree::lanes
