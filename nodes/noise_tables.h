// The lattice tables behind noise, as plain data so that generated code can
// embed them as constants.
#pragma once

#include <array>
#include <cstdint>

namespace shadetree {

inline constexpr int noise_table_size = 256;  // n in Perlin & Hoffert 1989 section 2.3
inline constexpr std::uint32_t default_noise_seed = 1989;

// Each noise table holds n entries and then entry 0 once more, so that the
// entries at i and at (i + 1) mod n, a pair of neighbouring lattice cells,
// are adjacent in memory: a vector backend reads both as one 64-bit lookup
// per lane (gather256_pair in nodes/lane_scalar.h).
using PermutationTable = std::array<std::int32_t, noise_table_size + 1>;
using GradientTable = std::array<float, noise_table_size + 1>;

struct NoiseTables {
  // The hashed gradients below interleaved, with gradient_x as the fourth:
  // (G[P[i]].x, G[P[i]].y, G[P[i]].z, G[i].x) per entry, a 4D noise knot's
  // whole gradient (nodes/semantics/noise4.h). A knot row's gradients,
  // entries i and i + 1, are 32 contiguous bytes, read with one load per
  // knot and lane where a vector backend reads memory lane by lane. First,
  // so that tables aligned to 16 bytes keep its entries aligned.
  std::array<float, 4 * (noise_table_size + 1)> hashed_gradient_xyzw;
  PermutationTable permutation;                            // P: a permutation of 0..n-1
  GradientTable gradient_x;                                // G: unit vectors, as SoA
  GradientTable gradient_y;
  GradientTable gradient_z;
  // G[P[i]]: the last hash step and the gradient lookup composed into one
  // table, so that a knot's gradient is one lookup instead of two.
  GradientTable hashed_gradient_x;
  GradientTable hashed_gradient_y;
  GradientTable hashed_gradient_z;
};

// Tables for a seed, built as 1989 section 2.3 prescribes: P by a
// Fisher-Yates shuffle, G by rejection sampling in the unit ball then
// normalization, both drawing from splitmix64 seeded with `seed`.
NoiseTables make_noise_tables(std::uint32_t seed);

// Cached make_noise_tables; thread-safe; the reference stays valid.
const NoiseTables& noise_tables(std::uint32_t seed);

}  // namespace shadetree
