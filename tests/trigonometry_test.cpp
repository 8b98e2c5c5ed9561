// Sine and cosine of nodes/semantics/trigonometry.h against libm.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "nodes/semantics/trigonometry.h"

namespace shadetree::semantics {
namespace {

TEST(Trigonometry, AgreesWithLibmToAFewUlp) {
  for (float x = -100.0f; x <= 100.0f; x += 0.00731f) {
    EXPECT_NEAR(sine_of(x), std::sin(static_cast<double>(x)), 3e-7) << x;
    EXPECT_NEAR(cosine_of(x), std::cos(static_cast<double>(x)), 3e-7) << x;
  }
}

TEST(Trigonometry, StaysAccurateUpTo8192) {
  for (float x = 100.0f; x <= 8192.0f; x += 1.37f) {
    EXPECT_NEAR(sine_of(x), std::sin(static_cast<double>(x)), 1e-6) << x;
    EXPECT_NEAR(cosine_of(-x), std::cos(static_cast<double>(x)), 1e-6) << x;
  }
}

TEST(Trigonometry, KnownValuesAndSymmetry) {
  EXPECT_EQ(sine_of(0.0f), 0.0f);
  EXPECT_EQ(cosine_of(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(sine_of(1.5707963267948966f), 1.0f);
  EXPECT_NEAR(cosine_of(3.14159265358979f), -1.0f, 1e-7f);
  for (float x : {0.3f, 1.0f, 2.5f, 10.0f, 1000.0f}) {
    EXPECT_EQ(sine_of(-x), -sine_of(x));
    EXPECT_EQ(cosine_of(-x), cosine_of(x));
  }
}

TEST(Trigonometry, NonFiniteInputsGiveNaN) {
  EXPECT_TRUE(std::isnan(sine_of(std::numeric_limits<float>::infinity())));
  EXPECT_TRUE(std::isnan(cosine_of(std::numeric_limits<float>::quiet_NaN())));
  EXPECT_EQ(sine_of(1e30f), 0.0f);  // no digits of the phase left
  EXPECT_EQ(cosine_of(-3e7f), 0.0f);
}

}  // namespace
}  // namespace shadetree::semantics
