// The lattice tables behind noise, as plain data so that generated code can
// embed them as constants.
#pragma once

#include <array>
#include <cstdint>

namespace shadetree {

inline constexpr int noise_table_size = 256;  // n in Perlin & Hoffert 1989 section 2.3
inline constexpr std::uint32_t default_noise_seed = 1989;

struct NoiseTables {
  std::array<std::int32_t, noise_table_size> permutation;  // P: a permutation of 0..n-1
  std::array<float, noise_table_size> gradient_x;          // G: unit vectors, as SoA
  std::array<float, noise_table_size> gradient_y;
  std::array<float, noise_table_size> gradient_z;
  // G[P[i]]: the last hash step and the gradient lookup composed into one
  // table, so that a knot's gradient is one lookup instead of two.
  std::array<float, noise_table_size> hashed_gradient_x;
  std::array<float, noise_table_size> hashed_gradient_y;
  std::array<float, noise_table_size> hashed_gradient_z;
};

// Tables for a seed, built as 1989 section 2.3 prescribes: P by a
// Fisher-Yates shuffle, G by rejection sampling in the unit ball then
// normalization, both drawing from splitmix64 seeded with `seed`.
NoiseTables make_noise_tables(std::uint32_t seed);

// Cached make_noise_tables; thread-safe; the reference stays valid.
const NoiseTables& noise_tables(std::uint32_t seed);

}  // namespace shadetree
