// Pattern generators (nodes/semantics/patterns.h) against closed forms.
#include <gtest/gtest.h>

#include "nodes/semantics/patterns.h"

namespace shadetree::semantics {
namespace {

TEST(Swave, UnfilteredIsTheSquareWave) {
  EXPECT_EQ(swave(0.25f, 0.0f, 1.0f, 0.5f, 0.0f), 1.0f);
  EXPECT_EQ(swave(0.75f, 0.0f, 1.0f, 0.5f, 0.0f), 0.0f);
  EXPECT_EQ(swave(-0.25f, 0.0f, 1.0f, 0.5f, 0.0f), 0.0f);
  EXPECT_EQ(swave(1.1f, 0.0f, 1.0f, 0.3f, 0.0f), 1.0f);
}

// A box as wide as a whole period averages the wave to its duty cycle,
// wherever it is centred and however far from the origin.
TEST(Swave, AWholePeriodBoxAveragesToTheDuty) {
  for (float x : {0.0f, 0.13f, 0.5f, -7.3f, 1000.6f})
    for (float duty : {0.25f, 0.5f, 0.8f}) EXPECT_NEAR(swave(x, 1.0f, 1.0f, duty, 0.0f), duty, 1e-4f) << x;
}

// A box of width w centred on a rising edge covers half 0 and half 1.
TEST(Swave, AnEdgeFiltersToOneHalf) {
  EXPECT_NEAR(swave(0.0f, 0.2f, 1.0f, 0.5f, 0.0f), 0.5f, 1e-6f);
  EXPECT_NEAR(swave(0.5f, 0.1f, 1.0f, 0.5f, 0.0f), 0.5f, 1e-6f);
  // Inside a stripe, a narrow box sees only that stripe.
  EXPECT_NEAR(swave(0.25f, 0.1f, 1.0f, 0.5f, 0.0f), 1.0f, 1e-6f);
}

TEST(Swave, FrequencyScalesTheFilterWidthToo) {
  EXPECT_NEAR(swave(0.0f, 0.25f, 4.0f, 0.5f, 0.0f), 0.5f, 1e-6f);  // one period wide at frequency 4
  EXPECT_NEAR(swave(0.3f, 0.25f, 4.0f, 0.5f, 0.0f), 0.5f, 1e-6f);
}

TEST(Checker, AlternatesAcrossCells) {
  EXPECT_EQ(checker(0.5f, 0.5f, 0.5f), 0.0f);
  EXPECT_EQ(checker(1.5f, 0.5f, 0.5f), 1.0f);
  EXPECT_EQ(checker(1.5f, 1.5f, 0.5f), 0.0f);
  EXPECT_EQ(checker(-0.5f, 0.5f, 0.5f), 1.0f);
}

TEST(Julia, InteriorPointsSurviveEveryIteration) {
  EXPECT_EQ(julia(0.0f, 0.0f, 0.0f, 0.0f, 64.0f), 1.0f);  // z stays 0 for c = 0
  EXPECT_EQ(julia(3.0f, 0.0f, 0.0f, 0.0f, 64.0f), 0.0f);  // |z0| > 2 escapes at once
  // z0 = 1.5, c = 0: 1.5 -> 2.25 escapes after one step.
  EXPECT_FLOAT_EQ(julia(1.5f, 0.0f, 0.0f, 0.0f, 10.0f), 0.1f);
}

TEST(Julia, IterationsAreCappedAtTheDocumentedLimit) {
  EXPECT_EQ(julia(0.0f, 0.0f, 0.0f, 0.0f, 5000.0f), 1.0f);
}

TEST(Sines, StaysInTheUnitInterval) {
  for (float x = -5.0f; x < 5.0f; x += 0.37f)
    for (float y = -5.0f; y < 5.0f; y += 0.41f) {
      const float value = sines(x, y, 1.0f, 5.0f);
      EXPECT_GE(value, 0.0f);
      EXPECT_LE(value, 1.0f);
    }
  EXPECT_EQ(sines(1.0f, 2.0f, 1.0f, 0.0f), 0.0f);
}

// One term: ((sin(x + pi/2 sin(y/2)) + 1) (sin(y + pi/2 sin(x/2)) + 1)) / 4.
TEST(Sines, OneTermMatchesGardnersFormula) {
  const float x = 0.7f, y = -1.1f, half_pi = 1.57079632679f;
  const float expected =
      (std::sin(x + half_pi * std::sin(0.5f * y)) + 1.0f) * (std::sin(y + half_pi * std::sin(0.5f * x)) + 1.0f) / 4.0f;
  EXPECT_NEAR(sines(x, y, 1.0f, 1.0f), expected, 1e-6f);
}

}  // namespace
}  // namespace shadetree::semantics
