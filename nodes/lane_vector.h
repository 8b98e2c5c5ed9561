// Lane primitives for W samples at a time, in clang vector types:
// F = floatv<W>, I = intv<W>, M = intv<W> (all ones / zero per lane).
// Only compiled by clang (codegen/ops_bitcode.cpp), never by the host
// compiler. Each primitive does, per lane, exactly what its scalar twin in
// lane_scalar.h does, so the semantics compute the same values either way.
#pragma once

#include <array>
#include <cstdint>

#include "nodes/noise_tables.h"

namespace shadetree::lanes {

template <int W>
using floatv = float __attribute__((ext_vector_type(W)));
template <int W>
using intv = std::int32_t __attribute__((ext_vector_type(W)));

// Table lookups are declared here and defined by the code generator
// (codegen/table_lookups.cpp), which picks the instruction sequence per
// target: a hardware gather, one load per lane, or permutes of registers.
// gather256_gradients and gather256_gradient_pairs, the three hashed
// gradient tables at index (and with pairs at index + 1: out is x at both,
// then y, then z), gather256_knot_rows, those pairs of the four rows of
// knots around lattice cell (i, j, k) (nodes/semantics/noise.h,
// for_each_noise_row: out is row 0's six, then row 1's, ...), and
// gather256_knot_rows4, the 4D gradient pairs (x, y, z, w) of the eight
// rows around cell (i, j, k, l) (nodes/semantics/noise4.h: row 4 dl + 2 dk
// + dj), exist only in this lane (the semantics ask whether they do).
#define SHADETREE_VECTOR_GATHERS(W)                                                                          \
  extern "C" void st_gather_f32_w##W(floatv<W>* out, const float* table, const intv<W>* index);             \
  extern "C" void st_gather_i32_w##W(intv<W>* out, const std::int32_t* table, const intv<W>* index);        \
  extern "C" void st_gather256_f32_w##W(floatv<W>* out, const float* table, const intv<W>* index);          \
  extern "C" void st_gather256_i32_w##W(intv<W>* out, const std::int32_t* table, const intv<W>* index);       \
  extern "C" void st_gather256_pair_f32_w##W(floatv<W>* at, floatv<W>* next, const float* table,             \
                                             const intv<W>* index);                                          \
  extern "C" void st_gather256_pair_i32_w##W(intv<W>* at, intv<W>* next, const std::int32_t* table,          \
                                             const intv<W>* index);                                          \
  extern "C" void st_gather_small_f32_w##W(floatv<W>* out, const float* table, std::int32_t count,           \
                                           std::int32_t stride, const intv<W>* index);                      \
  extern "C" void st_gather256_gradients_w##W(floatv<W>* out, const NoiseTables* tables, const intv<W>* index); \
  extern "C" void st_gather256_gradient_pairs_w##W(floatv<W>* out, const NoiseTables* tables,                  \
                                                   const intv<W>* index);                                     \
  extern "C" void st_gather256_knot_rows_w##W(floatv<W>* out, const NoiseTables* tables, const intv<W>* cell); \
  extern "C" void st_gather256_knot_rows4_w##W(floatv<W>* out, const NoiseTables* tables, const intv<W>* cell);

SHADETREE_VECTOR_GATHERS(4)
SHADETREE_VECTOR_GATHERS(8)
SHADETREE_VECTOR_GATHERS(16)
#undef SHADETREE_VECTOR_GATHERS

#define SHADETREE_VECTOR_LANES(W)                                                                             \
  inline floatv<W> select(intv<W> mask, floatv<W> a, floatv<W> b) { return mask ? a : b; }                  \
  inline intv<W> select(intv<W> mask, intv<W> a, intv<W> b) { return mask ? a : b; }                        \
  inline bool any(intv<W> mask) { return __builtin_reduce_or(mask) != 0; }                                  \
  inline intv<W> both(intv<W> a, intv<W> b) { return a & b; }                                               \
  inline intv<W> either(intv<W> a, intv<W> b) { return a | b; }                                             \
  inline intv<W> negate(intv<W> a) { return ~a; }                                                           \
  inline intv<W> differ(intv<W> a, intv<W> b) { return a ^ b; }                                             \
  inline floatv<W> floor(floatv<W> x) { return __builtin_elementwise_floor(x); }                            \
  inline floatv<W> abs(floatv<W> x) { return __builtin_elementwise_abs(x); }                                \
  inline floatv<W> sqrt(floatv<W> x) { return __builtin_elementwise_sqrt(x); }                              \
  inline floatv<W> min(floatv<W> a, floatv<W> b) { return a < b ? a : b; }                                  \
  inline floatv<W> max(floatv<W> a, floatv<W> b) { return a > b ? a : b; }                                  \
  inline intv<W> min(intv<W> a, intv<W> b) { return a < b ? a : b; }                                        \
  inline intv<W> max(intv<W> a, intv<W> b) { return a > b ? a : b; }                                        \
  inline intv<W> to_int(floatv<W> x) { return __builtin_convertvector(x, intv<W>); }                        \
  inline floatv<W> to_float(intv<W> i) { return __builtin_convertvector(i, floatv<W>); }                    \
  inline intv<W> to_bits(floatv<W> x) { return __builtin_bit_cast(intv<W>, x); }                             \
  inline floatv<W> from_bits(intv<W> bits) { return __builtin_bit_cast(floatv<W>, bits); }                   \
  inline floatv<W> gather(const float* table, intv<W> index) {                                              \
    floatv<W> result;                                                                                        \
    st_gather_f32_w##W(&result, table, &index);                                                              \
    return result;                                                                                           \
  }                                                                                                          \
  inline intv<W> gather(const std::int32_t* table, intv<W> index) {                                         \
    intv<W> result;                                                                                          \
    st_gather_i32_w##W(&result, table, &index);                                                              \
    return result;                                                                                           \
  }                                                                                                          \
  inline floatv<W> gather256(const float* table, intv<W> index) {                                           \
    floatv<W> result;                                                                                        \
    st_gather256_f32_w##W(&result, table, &index);                                                           \
    return result;                                                                                           \
  }                                                                                                          \
  inline intv<W> gather256(const std::int32_t* table, intv<W> index) {                                      \
    intv<W> result;                                                                                          \
    st_gather256_i32_w##W(&result, table, &index);                                                           \
    return result;                                                                                           \
  }                                                                                                          \
  inline std::array<floatv<W>, 2> gather256_pair(const float* table, intv<W> index) {                       \
    std::array<floatv<W>, 2> result;                                                                         \
    st_gather256_pair_f32_w##W(&result[0], &result[1], table, &index);                                       \
    return result;                                                                                           \
  }                                                                                                          \
  inline std::array<intv<W>, 2> gather256_pair(const std::int32_t* table, intv<W> index) {                  \
    std::array<intv<W>, 2> result;                                                                           \
    st_gather256_pair_i32_w##W(&result[0], &result[1], table, &index);                                       \
    return result;                                                                                           \
  }                                                                                                          \
  inline floatv<W> gather_small(const float* table, std::int32_t count, std::int32_t stride, intv<W> index) { \
    floatv<W> result;                                                                                        \
    st_gather_small_f32_w##W(&result, table, count, stride, &index);                                         \
    return result;                                                                                           \
  }                                                                                                          \
  inline std::array<floatv<W>, 3> gather256_gradients(const NoiseTables& tables, intv<W> index) {            \
    std::array<floatv<W>, 3> result;                                                                         \
    st_gather256_gradients_w##W(result.data(), &tables, &index);                                             \
    return result;                                                                                           \
  }                                                                                                          \
  inline std::array<std::array<floatv<W>, 2>, 3> gather256_gradient_pairs(const NoiseTables& tables,        \
                                                                          intv<W> index) {                  \
    floatv<W> result[6];                                                                                     \
    st_gather256_gradient_pairs_w##W(result, &tables, &index);                                               \
    return {{{result[0], result[1]}, {result[2], result[3]}, {result[4], result[5]}}};                       \
  }                                                                                                          \
  inline std::array<std::array<std::array<floatv<W>, 2>, 3>, 4> gather256_knot_rows(                          \
      const NoiseTables& tables, intv<W> i, intv<W> j, intv<W> k) {                                          \
    const intv<W> cell[3] = {i, j, k};                                                                       \
    floatv<W> r[24];                                                                                         \
    st_gather256_knot_rows_w##W(r, &tables, cell);                                                           \
    return {{{{{r[0], r[1]}, {r[2], r[3]}, {r[4], r[5]}}},                                                   \
             {{{r[6], r[7]}, {r[8], r[9]}, {r[10], r[11]}}},                                                 \
             {{{r[12], r[13]}, {r[14], r[15]}, {r[16], r[17]}}},                                             \
             {{{r[18], r[19]}, {r[20], r[21]}, {r[22], r[23]}}}}};                                           \
  }                                                                                                          \
  inline std::array<std::array<std::array<floatv<W>, 2>, 4>, 8> gather256_knot_rows4(                         \
      const NoiseTables& tables, intv<W> i, intv<W> j, intv<W> k, intv<W> l) {                               \
    const intv<W> cell[4] = {i, j, k, l};                                                                    \
    floatv<W> r[64];                                                                                         \
    st_gather256_knot_rows4_w##W(r, &tables, cell);                                                          \
    std::array<std::array<std::array<floatv<W>, 2>, 4>, 8> rows;                                             \
    for (int row = 0; row < 8; ++row)                                                                        \
      for (int axis = 0; axis < 4; ++axis)                                                                   \
        for (int knot = 0; knot < 2; ++knot) rows[row][axis][knot] = r[8 * row + 2 * axis + knot];            \
    return rows;                                                                                             \
  }

SHADETREE_VECTOR_LANES(4)
SHADETREE_VECTOR_LANES(8)
SHADETREE_VECTOR_LANES(16)
#undef SHADETREE_VECTOR_LANES

}  // namespace shadetree::lanes
