// exp, log and pow of nodes/semantics/exponential.h against libm.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "nodes/semantics/exponential.h"

namespace shadetree::semantics {
namespace {

constexpr float infinity = std::numeric_limits<float>::infinity();

double relative_error(float value, double reference) {
  if (reference == 0.0) return std::fabs(value);
  return std::fabs(value - reference) / std::fabs(reference);
}

TEST(Exponential, AgreesWithLibmToAFewUlp) {
  for (float x = -87.0f; x <= 88.0f; x += 0.0137f)
    ASSERT_LT(relative_error(exponential_of(x), std::exp(static_cast<double>(x))), 3e-7) << x;
  // Subnormal results: within two subnormal steps.
  for (float x = -103.0f; x < -88.0f; x += 0.37f)
    ASSERT_NEAR(exponential_of(x), std::exp(static_cast<double>(x)), 2.9e-45) << x;
}

TEST(Exponential, EdgesMatchLibm) {
  EXPECT_EQ(exponential_of(0.0f), 1.0f);
  EXPECT_EQ(exponential_of(100.0f), infinity);
  EXPECT_EQ(exponential_of(-infinity), 0.0f);
  EXPECT_EQ(exponential_of(-120.0f), 0.0f);
  EXPECT_TRUE(std::isnan(exponential_of(std::numeric_limits<float>::quiet_NaN())));
}

TEST(Logarithm, AgreesWithLibmToAFewUlp) {
  for (float x = 1e-30f; x < 1e30f; x *= 1.0137f)
    ASSERT_NEAR(logarithm_of(x), std::log(static_cast<double>(x)), 3e-7 * std::max(1.0, std::fabs(std::log(static_cast<double>(x)))))
        << x;
  EXPECT_NEAR(logarithm_of(1e-40f), std::log(1e-40), 1e-5);  // subnormal
}

TEST(Logarithm, EdgesMatchLibm) {
  EXPECT_EQ(logarithm_of(1.0f), 0.0f);
  EXPECT_EQ(logarithm_of(0.0f), -infinity);
  EXPECT_EQ(logarithm_of(infinity), infinity);
  EXPECT_TRUE(std::isnan(logarithm_of(-1.0f)));
}

// exp(y log x) carries log's rounding times |y log x| into the result.
TEST(Power, AgreesWithLibmForShadingRanges) {
  for (float x = 0.001f; x <= 20.0f; x *= 1.07f)
    for (float y : {-3.0f, -0.5f, 0.1f, 0.7370f, 1.5f, 3.0f, 7.0f}) {
      const double exponent = std::fabs(y * std::log(static_cast<double>(x)));
      ASSERT_LT(relative_error(power_of(x, y), std::pow(static_cast<double>(x), static_cast<double>(y))),
                1.5e-7 * (2.0 + exponent))
          << x << "^" << y;
    }
}

TEST(Power, SpecialCasesMatchLibm) {
  EXPECT_EQ(power_of(0.0f, 2.0f), 0.0f);
  EXPECT_EQ(power_of(0.0f, -1.0f), infinity);
  EXPECT_EQ(power_of(7.0f, 0.0f), 1.0f);
  EXPECT_EQ(power_of(std::numeric_limits<float>::quiet_NaN(), 0.0f), 1.0f);
  EXPECT_EQ(power_of(0.3f, 1.0f), 0.3f);
  EXPECT_EQ(power_of(1.0f, 123.0f), 1.0f);
  EXPECT_NEAR(power_of(-2.0f, 3.0f), -8.0f, 1e-5f);
  EXPECT_NEAR(power_of(-2.0f, 2.0f), 4.0f, 1e-5f);
  EXPECT_TRUE(std::isnan(power_of(-2.0f, 0.5f)));
}

}  // namespace
}  // namespace shadetree::semantics
