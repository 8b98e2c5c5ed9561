// Paper identities of the componentwise operators (nodes/semantics/arithmetic.h).
#include <gtest/gtest.h>

#include "nodes/semantics/arithmetic.h"

namespace shadetree::semantics {
namespace {

// Perlin & Hoffert 1989 section 2.3: bias_b(0) = 0, bias_b(1/2) = b, bias_b(1) = 1.
TEST(Bias, FixesTheEndsAndMapsHalfToB) {
  for (float b : {0.1f, 0.25f, 0.5f, 0.7f, 0.95f}) {
    EXPECT_EQ(bias(0.0f, b), 0.0f) << "b = " << b;
    EXPECT_NEAR(bias(0.5f, b), b, 1e-6f) << "b = " << b;
    EXPECT_EQ(bias(1.0f, b), 1.0f) << "b = " << b;
  }
}

TEST(Bias, HalfIsTheIdentity) {
  for (float t = 0.0f; t <= 1.0f; t += 0.0625f) EXPECT_EQ(bias(t, 0.5f), t);
}

// 1989 section 2.3: gain_g(1/4) = (1-g)/2, gain_g(1/2) = 1/2, gain_g(3/4) = (1+g)/2.
TEST(Gain, QuartersMapToTheirPaperValues) {
  for (float g : {0.1f, 0.3f, 0.5f, 0.8f, 0.9f}) {
    EXPECT_EQ(gain(0.0f, g), 0.0f) << "g = " << g;
    EXPECT_NEAR(gain(0.25f, g), (1.0f - g) / 2.0f, 1e-6f) << "g = " << g;
    EXPECT_NEAR(gain(0.5f, g), 0.5f, 1e-6f) << "g = " << g;
    EXPECT_NEAR(gain(0.75f, g), (1.0f + g) / 2.0f, 1e-6f) << "g = " << g;
    EXPECT_EQ(gain(1.0f, g), 1.0f) << "g = " << g;
  }
}

TEST(Gain, HalfIsTheIdentity) {
  for (float t = 0.0f; t <= 1.0f; t += 0.0625f) EXPECT_NEAR(gain(t, 0.5f), t, 1e-7f);
}

TEST(Mod, TakesTheSignOfTheDivisor) {
  EXPECT_FLOAT_EQ(mod(5.5f, 2.0f), 1.5f);
  EXPECT_FLOAT_EQ(mod(-0.5f, 2.0f), 1.5f);
  EXPECT_FLOAT_EQ(mod(0.5f, -2.0f), -1.5f);
}

TEST(Smoothstep, IsClampedHermite) {
  EXPECT_EQ(smoothstep(0.0f, 1.0f, -1.0f), 0.0f);
  EXPECT_EQ(smoothstep(0.0f, 1.0f, 0.5f), 0.5f);
  EXPECT_FLOAT_EQ(smoothstep(0.0f, 1.0f, 0.25f), 0.15625f);
  EXPECT_EQ(smoothstep(0.0f, 1.0f, 2.0f), 1.0f);
}

TEST(Remap, MapsEndpointsToEndpoints) {
  EXPECT_FLOAT_EQ(remap(-1.0f, -1.0f, 1.0f, 0.0f, 10.0f), 0.0f);
  EXPECT_FLOAT_EQ(remap(0.0f, -1.0f, 1.0f, 0.0f, 10.0f), 5.0f);
  EXPECT_FLOAT_EQ(remap(1.0f, -1.0f, 1.0f, 0.0f, 10.0f), 10.0f);
}

}  // namespace
}  // namespace shadetree::semantics
