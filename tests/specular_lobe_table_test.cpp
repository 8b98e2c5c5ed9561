// The specular lobe from a table (scene/specular_lobe_table.h) against
// pow in double precision, over every float of its domain a dense grid
// reaches.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/lighting.h"
#include "scene/specular_lobe_table.h"

namespace shadetree {
namespace {

// The largest difference from pow over [floor, 1.0000002] (a half vector
// of unit vectors can round a hair past 1).
double largest_error(float exponent) {
  const SpecularLobeTable lobe(exponent);
  double largest = 0.0;
  constexpr int samples = 1 << 20;
  for (int i = 0; i <= samples; ++i) {
    const float base = lobe.floor() + static_cast<float>(i) / samples * (1.0000002f - lobe.floor());
    const double exact = std::pow(static_cast<double>(base), static_cast<double>(exponent));
    largest = std::max(largest, std::fabs(lobe(base) - exact));
  }
  return largest;
}

TEST(SpecularLobeTable, AboveTheFloorWithinHalfOfItForEveryExponentFromOne) {
  // The default material's, roughness 0.02's (the sharpest there is) and
  // exponents between, where the floor and the curvature trade.
  for (const float exponent :
       {1.0f, 1.1f, 1.5f, 2.0f, 5.0f, specular_exponent(SurfaceMaterial{}.roughness), 50.0f, 500.0f,
        specular_exponent(0.0f)})
    EXPECT_LE(largest_error(exponent), std::ldexp(1.0, -17)) << "exponent " << exponent;
}

TEST(SpecularLobeTable, BelowTheFloorTheLobeIsLeftOut) {
  const float exponent = specular_exponent(SurfaceMaterial{}.roughness);
  const SpecularLobeTable lobe(exponent);
  EXPECT_FLOAT_EQ(std::pow(lobe.floor(), exponent), std::ldexp(1.0f, -16));
  EXPECT_EQ(lobe(std::nextafter(lobe.floor(), 0.0f)), 0.0f);
  EXPECT_GT(lobe(lobe.floor()), 0.0f);
  EXPECT_EQ(lobe(std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(SpecularLobeTable, TheEndsAreExact) {
  const SpecularLobeTable lobe(specular_exponent(SurfaceMaterial{}.roughness));
  EXPECT_EQ(lobe(1.0f), 1.0f);
  EXPECT_EQ(SpecularLobeTable(0.0f)(0.0f), 1.0f);  // roughness 1: a constant lobe, as pow(0, 0)
  EXPECT_EQ(SpecularLobeTable(0.0f)(0.5f), 1.0f);
}

TEST(SpecularLobeTable, ExponentsBelowOneTakePow) {
  const SpecularLobeTable lobe(0.5f);
  for (const float base : {1e-9f, 0.01f, 0.3f, 0.99f}) EXPECT_EQ(lobe(base), std::pow(base, 0.5f)) << base;
}

}  // namespace
}  // namespace shadetree
