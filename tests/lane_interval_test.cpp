// The interval lane primitives (nodes/lane_interval.h) and the interval
// forms of the transcendental functions: each encloses what the float
// lane computes at every point of random boxes, and NaN becomes
// everything.
#include <gtest/gtest.h>

#include <vector>

#include <cmath>
#include <functional>
#include <random>

#include "nodes/interval_frame.h"
#include "nodes/noise_tables.h"
#include "nodes/semantics/noise_intervals.h"

namespace shadetree {
namespace {

using lanes::encloses;
using lanes::Interval;

// Random boxes: centres near 0, far out and at 1e4; widths from 0 up.
struct BoxSource {
  std::mt19937 random{22};

  Interval box() {
    const float centres[] = {uniform(-3, 3), uniform(-60, 60), 1e4f + uniform(-3, 3), -uniform(0, 7),
                             std::round(uniform(-4, 4))};
    const float widths[] = {0.0f, 1e-3f, 0.05f, 0.5f, 3.0f, 40.0f};
    const float centre = centres[pick(std::size(centres))], width = widths[pick(std::size(widths))] * uniform(0, 1);
    return {centre - width, centre + width};
  }
  float inside(Interval x) {
    const int which = static_cast<int>(pick(4));
    return which == 0 ? x.lo : which == 1 ? x.hi : std::min(x.hi, x.lo + (x.hi - x.lo) * uniform(0, 1));
  }
  float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(random); }
  std::size_t pick(std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(random); }
};

void expect_unary_encloses(const char* name, const std::function<Interval(Interval)>& interval,
                           const std::function<float(float)>& lane) {
  BoxSource source;
  for (int b = 0; b < 4000; ++b) {
    const Interval x = source.box();
    const Interval result = interval(x);
    for (int s = 0; s < 32; ++s) {
      const float v = source.inside(x);
      ASSERT_TRUE(encloses(result, lane(v)))
          << name << " over [" << x.lo << ", " << x.hi << "] at " << v << ": " << lane(v) << " outside ["
          << result.lo << ", " << result.hi << "]";
    }
  }
}

void expect_binary_encloses(const char* name, const std::function<Interval(Interval, Interval)>& interval,
                            const std::function<float(float, float)>& lane) {
  BoxSource source;
  for (int b = 0; b < 4000; ++b) {
    const Interval x = source.box(), y = source.box();
    const Interval result = interval(x, y);
    for (int s = 0; s < 32; ++s) {
      const float u = source.inside(x), v = source.inside(y);
      ASSERT_TRUE(encloses(result, lane(u, v)))
          << name << " over [" << x.lo << ", " << x.hi << "] x [" << y.lo << ", " << y.hi << "] at " << u << ", " << v
          << ": " << lane(u, v) << " outside [" << result.lo << ", " << result.hi << "]";
    }
  }
}

TEST(LaneInterval, ArithmeticEnclosesTheFloatResults) {
  expect_binary_encloses("add", [](Interval a, Interval b) { return a + b; }, [](float a, float b) { return a + b; });
  expect_binary_encloses("sub", [](Interval a, Interval b) { return a - b; }, [](float a, float b) { return a - b; });
  expect_binary_encloses("mul", [](Interval a, Interval b) { return a * b; }, [](float a, float b) { return a * b; });
  expect_binary_encloses("div", [](Interval a, Interval b) { return a / b; }, [](float a, float b) { return a / b; });
  expect_binary_encloses("min", [](Interval a, Interval b) { return lanes::min(a, b); },
                         [](float a, float b) { return lanes::min(a, b); });
  expect_binary_encloses("max", [](Interval a, Interval b) { return lanes::max(a, b); },
                         [](float a, float b) { return lanes::max(a, b); });
  expect_unary_encloses("floor", [](Interval x) { return lanes::floor(x); }, [](float x) { return std::floor(x); });
  expect_unary_encloses("abs", [](Interval x) { return lanes::abs(x); }, [](float x) { return std::fabs(x); });
  expect_unary_encloses("square", [](Interval x) { return lanes::square(x); }, [](float x) { return x * x; });
  expect_unary_encloses("sqrt", [](Interval x) { return lanes::sqrt(x); }, [](float x) { return std::sqrt(x); });
}

TEST(LaneInterval, TranscendentalFormsEncloseTheLaneForms) {
  expect_unary_encloses("exp", [](Interval x) { return lanes::exponential_of(x * 0.1f); },
                        [](float x) { return semantics::exponential_of(x * 0.1f); });
  expect_unary_encloses("log", [](Interval x) { return lanes::logarithm_of(x); },
                        [](float x) { return semantics::logarithm_of(x); });
  expect_unary_encloses("sin", [](Interval x) { return lanes::sine_of(x); }, [](float x) { return semantics::sine_of(x); });
  expect_unary_encloses("cos", [](Interval x) { return lanes::cosine_of(x); },
                        [](float x) { return semantics::cosine_of(x); });
}

TEST(LaneInterval, ComparisonsAreCertainOnlyWhereEveryPointAgrees) {
  BoxSource source;
  for (int b = 0; b < 4000; ++b) {
    const Interval x = source.box(), y = source.box();
    const lanes::IntervalMask less = x < y, equal = x == y;
    for (int s = 0; s < 32; ++s) {
      const float u = source.inside(x), v = source.inside(y);
      ASSERT_TRUE(u < v ? less.may_hold : less.may_fail);
      ASSERT_TRUE(u == v ? equal.may_hold : equal.may_fail);
    }
  }
  EXPECT_FALSE((Interval{1, 2} < Interval{3, 4}).may_fail);
  EXPECT_FALSE((Interval{3, 4} < Interval{1, 2}).may_hold);
}

TEST(LaneInterval, SelectTakesTheHullWhereTheMaskIsUncertain) {
  const Interval a{0, 1}, b{5, 6};
  const Interval uncertain = lanes::select(Interval{0, 2} < 1.0f, a, b);
  EXPECT_EQ(uncertain.lo, 0.0f);
  EXPECT_EQ(uncertain.hi, 6.0f);
  EXPECT_EQ(lanes::select(Interval{0, 0.5f} < 1.0f, a, b).hi, 1.0f);
  EXPECT_EQ(lanes::select(Interval{2, 3} < 1.0f, a, b).lo, 5.0f);
}

TEST(LaneInterval, NaNBecomesEverything) {
  EXPECT_TRUE(lanes::is_everything(lanes::sqrt(Interval{-1, 4})));
  EXPECT_TRUE(lanes::is_everything(Interval{1, 2} / Interval{-1, 1}));
  EXPECT_TRUE(lanes::is_everything(Interval{0, 1} * Interval{1, lanes::infinity}));
  EXPECT_TRUE(lanes::is_everything(Interval(std::nanf(""))));
  EXPECT_TRUE(lanes::is_everything(lanes::everything() + 1.0f));
  // The lane form of max(NaN, 0) is 0, so clamping everything is not NaN.
  const Interval clamped = lanes::min(lanes::max(lanes::everything(), 0.0f), 1.0f);
  EXPECT_EQ(clamped.lo, 0.0f);
  EXPECT_EQ(clamped.hi, 1.0f);
  EXPECT_TRUE(lanes::is_everything(lanes::max(0.0f, lanes::everything())));
}

TEST(LaneInterval, GatherTakesTheHullOfTheIndexRange) {
  const float table[] = {3, -1, 4, 1, 5};
  const Interval all = lanes::gather(table, lanes::IntervalInt{1, 3});
  EXPECT_EQ(all.lo, -1.0f);
  EXPECT_EQ(all.hi, 4.0f);
  // A range over a large table (an image, a distance grid) is not searched.
  const std::vector<float> large(lanes::max_hull_entries + 1, 0.5f);
  EXPECT_TRUE(lanes::is_everything(lanes::gather(large.data(), lanes::IntervalInt{0, lanes::max_hull_entries})));
}

// The premise of noise's and improved noise's proven ranges
// (nodes/semantics/noise_intervals.h): with weights w(t), w(1 - t) summing
// to 1, w(t) t^2 + w(1 - t) (1 - t)^2 <= 1/4 on [0, 1].
TEST(NoiseRange, WeightedSquaredOffsetsStayWithinAQuarter) {
  auto fade = [](double t) { return t * t * t * (t * (t * 6 - 15) + 10); };
  auto drop_off = [](double t) { return (t * 2 - 3) * t * t + 1; };
  for (int i = 0; i <= 100000; ++i) {
    const double t = i / 100000.0, s = 1 - t;
    ASSERT_LE(drop_off(t) * t * t + drop_off(s) * s * s, 0.25 + 1e-12) << t;
    ASSERT_LE((1 - fade(t)) * t * t + fade(t) * s * s, 0.25 + 1e-12) << t;
  }
}

// Noise over a box is bounded cell by cell while the box's widths add up
// to at most max_enclosed_noise_width: a long thin box (a cell of the
// bounds under a noise of stretched P) keeps a useful bound; a box past
// the sum gets the proven range, which its cells would nearly reach.
TEST(NoiseRange, CellsAreEnumeratedWhileTheBoxIsNarrowOverall) {
  const NoiseTables& tables = noise_tables(0);
  const auto noise_over = [&](float cx, float wx, float wyz) {
    const Interval x{cx - wx / 2, cx + wx / 2}, y{2.11f - wyz / 2, 2.11f + wyz / 2}, z{5.3f - wyz / 2, 5.3f + wyz / 2};
    return lanes::noise_on_axes(tables, x, y, z, semantics::lattice_axis(x), semantics::lattice_axis(y),
                                semantics::lattice_axis(z));
  };
  const float range = lanes::noise_bound + lanes::lattice_rounding_margin;
  const float long_side = lanes::max_enclosed_noise_width - 0.1f;
  for (float cx : {0.37f, 3.9f, 7.2f}) {
    const Interval thin = noise_over(cx, long_side, 0.02f);
    EXPECT_LT(thin.hi - thin.lo, 2.0f * range - 0.1f) << cx;
    const Interval over = noise_over(cx, long_side, 0.2f);
    EXPECT_EQ(over.lo, -range) << cx;
    EXPECT_EQ(over.hi, range) << cx;
  }
}

}  // namespace
}  // namespace shadetree
