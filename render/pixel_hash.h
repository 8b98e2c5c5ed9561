// Random numbers that depend only on what they are for (a pixel, a
// sample), so that images do not depend on the thread count or the order
// in which tiles and rays are processed.
#pragma once

#include <cstdint>

namespace shadetree {

// A 32-bit integer hash (Wellons' lowbias32).
inline std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// The top 24 bits as a float in [0, 1).
inline float unit_float(std::uint32_t bits) { return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f); }

// A hash of pixel (column, row) and an index (of a sample, a light...).
inline std::uint32_t pixel_hash(int column, int row, int index) {
  return hash32(static_cast<std::uint32_t>(column) * 73856093u ^ static_cast<std::uint32_t>(row) * 19349663u ^
                static_cast<std::uint32_t>(index) * 83492791u);
}

}  // namespace shadetree
