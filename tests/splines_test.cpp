// Splines and tables (nodes/semantics/splines.h).
#include <gtest/gtest.h>

#include "nodes/semantics/splines.h"

namespace shadetree::semantics {
namespace {

const float knots[] = {5.0f, 0.0f, 1.0f, 4.0f, 2.0f, -3.0f};  // 6 knots, 3 segments

TEST(Spline, CatmullRomPassesThroughTheInnerKnots) {
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::catmull_rom, 0.0f), 0.0f);
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::catmull_rom, 1.0f / 3.0f), 1.0f);
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::catmull_rom, 2.0f / 3.0f), 4.0f);
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::catmull_rom, 1.0f), 2.0f);
}

// Midway between k1 and k2: (-k0 + 9 k1 + 9 k2 - k3) / 16.
TEST(Spline, CatmullRomMidpointMatchesTheBasis) {
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::catmull_rom, 1.0f / 6.0f), (-5.0f + 0.0f + 9.0f - 4.0f) / 16.0f);
}

TEST(Spline, LinearInterpolatesAndClamps) {
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::linear, 0.1f), 2.5f);
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::linear, -1.0f), 5.0f);
  EXPECT_FLOAT_EQ(spline(knots, 6, 1, 0, SplineBasis::linear, 2.0f), -3.0f);
}

TEST(Spline, StepHoldsEachKnotForItsShareOfTheInterval) {
  EXPECT_EQ(spline(knots, 6, 1, 0, SplineBasis::step, 0.0f), 5.0f);
  EXPECT_EQ(spline(knots, 6, 1, 0, SplineBasis::step, 0.5f), 4.0f);
  EXPECT_EQ(spline(knots, 6, 1, 0, SplineBasis::step, 1.0f), -3.0f);
}

TEST(Spline, ReadsTheRequestedComponent) {
  const float colors[] = {0, 10, 20, 1, 11, 21};  // two rgb knots
  EXPECT_FLOAT_EQ(spline(colors, 2, 3, 1, SplineBasis::linear, 0.5f), 10.5f);
  EXPECT_FLOAT_EQ(spline(colors, 2, 3, 2, SplineBasis::linear, 1.0f), 21.0f);
}

// Prefix sums of {1, 3, 2}: {0, 1, 4, 6}.
const float entries[] = {1.0f, 3.0f, 2.0f};
const float prefix[] = {0.0f, 1.0f, 4.0f, 6.0f};

TEST(ColorTable, PointLookupPicksTheEntry) {
  EXPECT_EQ(color_table(entries, prefix, 3, 1, 0, 0.1f, 0.0f), 1.0f);
  EXPECT_EQ(color_table(entries, prefix, 3, 1, 0, 0.5f, 0.0f), 3.0f);
  EXPECT_EQ(color_table(entries, prefix, 3, 1, 0, 0.9f, 0.0f), 2.0f);
}

// Rhoades et al. 1992: the filtered lookup is the table's mean over the box.
TEST(ColorTable, FilteredLookupIsTheAverageOverTheBox) {
  EXPECT_NEAR(color_table(entries, prefix, 3, 1, 0, 0.5f, 1.0f), 2.0f, 1e-6f);      // whole table
  EXPECT_NEAR(color_table(entries, prefix, 3, 1, 0, 1.0f / 3.0f, 1.0f / 3.0f), 2.0f, 1e-6f);  // half 1, half 3
  EXPECT_NEAR(color_table(entries, prefix, 3, 1, 0, 0.5f, 0.1f), 3.0f, 1e-5f);      // inside one entry
}

TEST(Table2d, CornersAndCentre) {
  const float grid[] = {0.0f, 1.0f, 2.0f, 3.0f};  // rows {0,1} and {2,3}
  EXPECT_EQ(table2d(grid, 2, 2, 0.0f, 0.0f), 0.0f);
  EXPECT_EQ(table2d(grid, 2, 2, 1.0f, 0.0f), 1.0f);
  EXPECT_EQ(table2d(grid, 2, 2, 0.0f, 1.0f), 2.0f);
  EXPECT_EQ(table2d(grid, 2, 2, 1.0f, 1.0f), 3.0f);
  EXPECT_FLOAT_EQ(table2d(grid, 2, 2, 0.5f, 0.5f), 1.5f);
  EXPECT_EQ(table2d(grid, 1, 1, 0.7f, 0.2f), 0.0f);
}

}  // namespace
}  // namespace shadetree::semantics
