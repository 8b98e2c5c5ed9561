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
// gather256_knot_rows, the hashed gradients (x, y, z) of both knots of
// the four rows around lattice cell (i, j, k) (nodes/semantics/noise.h,
// for_each_noise_row: out is row 0's six, then row 1's, ...), and
// gather256_knot_rows4, the 4D gradient pairs (x, y, z, w) of the eight
// rows around cell (i, j, k, l) (nodes/semantics/noise4.h: row 4 dl + 2 dk
// + dj), exist only in this lane (the semantics ask whether they do).
// Given each axis's index, the second cell of an axis hashes as the index
// + 1; given both cells' indices (the _apart forms, cell[2 axis + d]),
// as its own index, which a periodic axis wraps.
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
  extern "C" void st_gather256_knot_rows_w##W(floatv<W>* out, const NoiseTables* tables, const intv<W>* cell); \
  extern "C" void st_gather256_knot_rows4_w##W(floatv<W>* out, const NoiseTables* tables, const intv<W>* cell); \
  extern "C" void st_gather256_knot_rows_apart_w##W(floatv<W>* out, const NoiseTables* tables,                  \
                                                    const intv<W>* cell);                                      \
  extern "C" void st_gather256_knot_rows4_apart_w##W(floatv<W>* out, const NoiseTables* tables,                 \
                                                     const intv<W>* cell);

SHADETREE_VECTOR_GATHERS(4)
SHADETREE_VECTOR_GATHERS(8)
SHADETREE_VECTOR_GATHERS(16)
#undef SHADETREE_VECTOR_GATHERS

// A knot-rows lookup's rows, row[axis][knot], from what it stored:
// r[(row * D + axis) * 2 + knot].
template <int W, std::size_t D>
using KnotRows = std::array<std::array<std::array<floatv<W>, 2>, D>, std::size_t{1} << (D - 1)>;
template <int W, std::size_t D>
KnotRows<W, D> knot_rows_from(const floatv<W>* r) {
  KnotRows<W, D> rows;
  for (std::size_t row = 0; row < rows.size(); ++row)
    for (std::size_t axis = 0; axis < D; ++axis)
      for (std::size_t knot = 0; knot < 2; ++knot) rows[row][axis][knot] = r[(row * D + axis) * 2 + knot];
  return rows;
}

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
  inline KnotRows<W, 3> gather256_knot_rows(const NoiseTables& tables, intv<W> i, intv<W> j, intv<W> k) {     \
    const intv<W> cell[3] = {i, j, k};                                                                       \
    floatv<W> r[24];                                                                                         \
    st_gather256_knot_rows_w##W(r, &tables, cell);                                                           \
    return knot_rows_from<W, 3>(r);                                                                          \
  }                                                                                                          \
  inline KnotRows<W, 4> gather256_knot_rows4(const NoiseTables& tables, intv<W> i, intv<W> j, intv<W> k,      \
                                             intv<W> l) {                                                    \
    const intv<W> cell[4] = {i, j, k, l};                                                                    \
    floatv<W> r[64];                                                                                         \
    st_gather256_knot_rows4_w##W(r, &tables, cell);                                                          \
    return knot_rows_from<W, 4>(r);                                                                          \
  }                                                                                                          \
  inline KnotRows<W, 3> gather256_knot_rows(const NoiseTables& tables, std::array<intv<W>, 2> i,              \
                                            std::array<intv<W>, 2> j, std::array<intv<W>, 2> k) {             \
    const intv<W> cell[6] = {i[0], i[1], j[0], j[1], k[0], k[1]};                                           \
    floatv<W> r[24];                                                                                         \
    st_gather256_knot_rows_apart_w##W(r, &tables, cell);                                                     \
    return knot_rows_from<W, 3>(r);                                                                          \
  }                                                                                                          \
  inline KnotRows<W, 4> gather256_knot_rows4(const NoiseTables& tables, std::array<intv<W>, 2> i,             \
                                             std::array<intv<W>, 2> j, std::array<intv<W>, 2> k,             \
                                             std::array<intv<W>, 2> l) {                                     \
    const intv<W> cell[8] = {i[0], i[1], j[0], j[1], k[0], k[1], l[0], l[1]};                               \
    floatv<W> r[64];                                                                                         \
    st_gather256_knot_rows4_apart_w##W(r, &tables, cell);                                                    \
    return knot_rows_from<W, 4>(r);                                                                          \
  }

SHADETREE_VECTOR_LANES(4)
SHADETREE_VECTOR_LANES(8)
SHADETREE_VECTOR_LANES(16)
#undef SHADETREE_VECTOR_LANES

}  // namespace shadetree::lanes
