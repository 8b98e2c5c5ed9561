// Noise generators against the properties Perlin 1985 / Perlin & Hoffert
// 1989 state, and Perlin 2002's reference implementation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <vector>

#include "nodes/semantics/noise.h"

namespace shadetree::semantics {
namespace {

const NoiseTables& tables() { return noise_tables(default_noise_seed); }

// A fixed pseudo-random walk through space, reproducible across runs.
struct SamplePoints {
  std::uint32_t state = 12345;
  float next(float range) {
    state = state * 1664525u + 1013904223u;
    return (static_cast<float>(state >> 8) / 16777216.0f * 2.0f - 1.0f) * range;
  }
};

TEST(NoiseTables, PermutationIsAPermutation) {
  const auto& permutation = tables().permutation;
  std::set<int> values(permutation.begin(), permutation.begin() + noise_table_size);
  EXPECT_EQ(values.size(), 256u);
  EXPECT_EQ(*values.begin(), 0);
  EXPECT_EQ(*values.rbegin(), 255);
}

TEST(NoiseTables, GradientsAreUnitVectors) {
  for (int i = 0; i < noise_table_size; ++i) {
    const float x = tables().gradient_x[i], y = tables().gradient_y[i], z = tables().gradient_z[i];
    EXPECT_NEAR(x * x + y * y + z * z, 1.0f, 1e-6f) << "gradient " << i;
  }
}

// Neighbouring cells read one paired lookup (gather256_pair), which needs
// slot 255's neighbour, slot 0, right after it.
TEST(NoiseTables, TablesRepeatTheirFirstEntryAfterTheLast) {
  for (int slot = 0; slot < noise_table_size; ++slot) {
    const auto pair = gather256_pair(tables().permutation.data(), slot);
    EXPECT_EQ(pair[0], tables().permutation[slot]);
    EXPECT_EQ(pair[1], tables().permutation[(slot + 1) % noise_table_size]) << "slot " << slot;
  }
  for (const GradientTable* table : {&tables().gradient_x, &tables().gradient_y, &tables().gradient_z,
                                     &tables().hashed_gradient_x, &tables().hashed_gradient_y,
                                     &tables().hashed_gradient_z}) {
    for (int slot = 0; slot < noise_table_size; ++slot) {
      const auto pair = gather256_pair(table->data(), slot);
      EXPECT_EQ(pair[0], (*table)[slot]);
      EXPECT_EQ(pair[1], (*table)[(slot + 1) % noise_table_size]) << "slot " << slot;
    }
  }
}

// A knot's whole gradient, in 3D and in 4D (where w is gradient_x at the
// slot, nodes/semantics/noise4.h), is one 16-byte read of the interleaved
// table (codegen/table_lookups.cpp), and a row's two knots 32 contiguous
// bytes: entry i holds slot i's, and entry 256 slot 0's.
TEST(NoiseTables, TheInterleavedGradientsAreTheHashedOnesThenTheUnhashedX) {
  const auto& interleaved = tables().hashed_gradient_xyzw;
  for (int slot = 0; slot <= noise_table_size; ++slot) {
    const int wrapped = slot % noise_table_size;
    EXPECT_EQ(interleaved[4 * slot + 0], tables().hashed_gradient_x[wrapped]) << "slot " << slot;
    EXPECT_EQ(interleaved[4 * slot + 1], tables().hashed_gradient_y[wrapped]) << "slot " << slot;
    EXPECT_EQ(interleaved[4 * slot + 2], tables().hashed_gradient_z[wrapped]) << "slot " << slot;
    EXPECT_EQ(interleaved[4 * slot + 3], tables().gradient_x[wrapped]) << "slot " << slot;
  }
  EXPECT_EQ(offsetof(NoiseTables, hashed_gradient_xyzw), 0u) << "first, so aligned tables keep it aligned";
}

TEST(NoiseTables, SeedsGiveDifferentTablesAndTheSameSeedTheSame) {
  EXPECT_EQ(make_noise_tables(7).permutation, make_noise_tables(7).permutation);
  EXPECT_NE(make_noise_tables(7).permutation, make_noise_tables(8).permutation);
}

// Each knot's linear gradient is zero at its own lattice point and the
// other knots' weights are zero there, so noise vanishes on the lattice.
TEST(Noise, IsZeroOnTheIntegerLattice) {
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k : {-300, -1, 0, 1, 17, 10000}) EXPECT_EQ(noise(tables(), float(i), float(j), float(k)), 0.0f);
}

// 1989 section 2.3 written out knot by knot, each lookup on its own:
// noise's paired lookups (neighbouring cells read together) give the same
// value to the bit, also where cells straddle the tables' wrap (cells 255
// and 256 on each axis).
TEST(Noise, PairedLookupsAgreeWithALookupPerKnot) {
  const NoiseTables& t = tables();
  auto phi = [&](int i) { return t.permutation[static_cast<std::size_t>(i & 255)]; };
  SamplePoints points;
  for (int n = 0; n < 20000; ++n) {
    auto coordinate = [&](float range) { return n % 2 ? points.next(range) : 255.0f + points.next(1) * 0.999f; };
    const float p[3] = {coordinate(600), coordinate(50), coordinate(50)};
    int cell[3];
    for (int axis = 0; axis < 3; ++axis) cell[axis] = static_cast<int>(std::floor(p[axis]));
    float sum = 0.0f;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const int slot = (cell[0] + i + phi(cell[1] + j + phi(cell[2] + k))) & 255;
          const float u = p[0] - float(cell[0]) - float(i), v = p[1] - float(cell[1]) - float(j),
                      w = p[2] - float(cell[2]) - float(k);
          const float slope =
              t.hashed_gradient_x[slot] * u + t.hashed_gradient_y[slot] * v + t.hashed_gradient_z[slot] * w;
          sum = sum + noise_weight(u) * noise_weight(v) * noise_weight(w) * slope;
        }
    EXPECT_EQ(noise(t, p[0], p[1], p[2]), sum) << p[0] << ", " << p[1] << ", " << p[2];
  }
}

TEST(Noise, IsBoundedAndNotConstant) {
  SamplePoints points;
  float low = 0, high = 0;
  for (int n = 0; n < 200000; ++n) {
    const float value = noise(tables(), points.next(50), points.next(50), points.next(50));
    low = std::min(low, value);
    high = std::max(high, value);
  }
  EXPECT_GE(low, -1.0f);
  EXPECT_LE(high, 1.0f);
  EXPECT_LT(low, -0.4f);
  EXPECT_GT(high, 0.4f);
}

TEST(Noise, IsPeriodicWithTheTableSize) {
  EXPECT_NEAR(noise(tables(), 0.3f, 1.7f, 2.2f), noise(tables(), 256.3f, 1.7f, 2.2f), 1e-4f);
}

TEST(Noise, HandlesHugeAndNegativeCoordinates) {
  EXPECT_TRUE(std::isfinite(noise(tables(), 3e9f, -7e12f, 1e30f)));
  EXPECT_TRUE(std::isfinite(noise(tables(), -0.5f, -1e4f, -123.25f)));
}

// A cell's hash index is floor(x) mod 256 for every float, computed here
// in double, and 0 for infinities and NaN; around +-2^31, where the
// conversion to int is clamped, too (2^31 - 128 is 128 mod 256).
TEST(Noise, CellHashIndexIsTheCellMod256ForEveryFloat) {
  const float infinity = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (float x : {infinity, -infinity, nan}) EXPECT_EQ(lattice_coordinate(x).hash_index, 0) << x;
  std::vector<float> xs = {0.0f, -0.0f, 0.5f, -0.5f, 255.5f, 256.0f, -256.5f, 16777217.0f, 2147483520.0f,
                           -2147483520.0f, 2147483648.0f, -2147483648.0f, 2147483904.0f, 1e30f, -1e30f};
  SamplePoints points;
  for (int n = 0; n < 20000; ++n) xs.push_back(std::ldexp(points.next(1), n % 40));
  for (float start : {2147483648.0f, -2147483648.0f, 1073741824.0f, -1073741824.0f}) {
    float x = start;
    for (int step = 0; step < 50; ++step, x = std::nextafter(x, 0.0f)) xs.push_back(x);
  }
  for (float x : xs) {
    const double cell = std::floor(static_cast<double>(x));
    const double mod = cell - std::floor(cell / 256.0) * 256.0;
    EXPECT_EQ(lattice_coordinate(x).hash_index, static_cast<int>(mod)) << x;
  }
}

TEST(Noise, NonFiniteCoordinatesStayInsideTheTables) {
  const float infinity = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (float bad : {infinity, -infinity, nan}) {
    EXPECT_FALSE(std::isfinite(noise(tables(), bad, 0.5f, 0.5f)));
    EXPECT_FALSE(std::isfinite(noise_improved(0.5f, bad, 0.5f)));
  }
}

TEST(Dnoise, AgreesWithFiniteDifferences) {
  SamplePoints points;
  const float h = 1e-2f;
  for (int n = 0; n < 500; ++n) {
    const float x = points.next(8), y = points.next(8), z = points.next(8);
    const Vec3<float> gradient = dnoise(tables(), x, y, z);
    // Central differences in double around the float point.
    auto at = [&](float dx, float dy, float dz) { return double(noise(tables(), x + dx, y + dy, z + dz)); };
    EXPECT_NEAR(gradient.x, (at(h, 0, 0) - at(-h, 0, 0)) / (2 * h), 2e-2) << x << "," << y << "," << z;
    EXPECT_NEAR(gradient.y, (at(0, h, 0) - at(0, -h, 0)) / (2 * h), 2e-2) << x << "," << y << "," << z;
    EXPECT_NEAR(gradient.z, (at(0, 0, h) - at(0, 0, -h)) / (2 * h), 2e-2) << x << "," << y << "," << z;
  }
}

// On the lattice only the knot's own gradient survives.
TEST(Dnoise, EqualsTheKnotGradientOnTheLattice) {
  const Vec3<float> at_origin = dnoise(tables(), 0.0f, 0.0f, 0.0f);
  const int index = tables().permutation[tables().permutation[tables().permutation[0]]];
  EXPECT_FLOAT_EQ(at_origin.x, tables().gradient_x[index]);
  EXPECT_FLOAT_EQ(at_origin.y, tables().gradient_y[index]);
  EXPECT_FLOAT_EQ(at_origin.z, tables().gradient_z[index]);
}

// Values of Perlin's 2002 reference implementation (Java, in double).
TEST(NoiseImproved, MatchesThePublishedReference) {
  EXPECT_NEAR(noise_improved(3.14f, 42.0f, 7.0f), 0.13691995878400012, 2e-6);
  EXPECT_EQ(noise_improved(1.0f, 2.0f, 3.0f), 0.0f);
}

TEST(Turbulence, OneOctaveIsAbsoluteNoise) {
  EXPECT_EQ(turbulence(tables(), 0.3f, 0.4f, 0.5f, 1.0f, 0.0f), std::fabs(noise(tables(), 0.3f, 0.4f, 0.5f)));
}

// 1985 appendix: octave i (scale 2^-i) is included while scale > pixelsize.
TEST(Turbulence, StopsAtTheFilterWidth) {
  const float x = 0.3f, y = 0.4f, z = 0.5f;
  float expected = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const float frequency = float(1 << i);
    expected += std::fabs(noise(tables(), x * frequency, y * frequency, z * frequency)) / frequency;
  }
  EXPECT_FLOAT_EQ(turbulence(tables(), x, y, z, 16.0f, 0.2f), expected);  // scales 1, 1/2, 1/4 > 0.2
  EXPECT_EQ(turbulence(tables(), x, y, z, 16.0f, 1.0f), 0.0f);           // no scale exceeds 1
}

TEST(Fbm, IsASumOfScaledOctaves) {
  const float x = 1.3f, y = -0.4f, z = 2.5f;
  const float expected = noise(tables(), x, y, z) + 0.5f * noise(tables(), 2 * x, 2 * y, 2 * z);
  EXPECT_FLOAT_EQ(fbm(tables(), x, y, z, 2.0f, 2.0f, 0.5f, 0.0f), expected);
}

}  // namespace
}  // namespace shadetree::semantics
