// The traced lanes (nodes/lane_trace.h): constants fold as GLSL computes
// them, exact identities add nothing, a repeated expression reuses its
// temporary only where it is in scope, literals read back exactly, table
// lookups name their arrays, and loop_while writes one rolled loop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "nodes/lane_trace.h"

namespace shadetree::lanes {
namespace {

int count_of(const std::string& text, const std::string& what) {
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

TEST(LaneTrace, ConstantsFoldAsGlslComputesThem) {
  Trace trace;
  TraceActivation active(trace);
  const TraceF product = TraceF(1.5f) * 2.0f;
  EXPECT_TRUE(product.constant);
  EXPECT_EQ(product.value, 3.0f);
  const TraceI wrapped = TraceI(std::numeric_limits<std::int32_t>::max()) + 1;
  EXPECT_EQ(wrapped.value, std::numeric_limits<std::int32_t>::min());
  EXPECT_EQ((TraceI(-8) >> 1).value, -4);
  EXPECT_EQ(to_bits(TraceF(1.0f)).value, 0x3f800000);
  EXPECT_EQ(select(TraceF(1.0f) < 2.0f, TraceF(7.0f), TraceF(9.0f)).value, 7.0f);
  EXPECT_EQ(trace.statements(), 0);
}

TEST(LaneTrace, ExactIdentitiesAddNoStatement) {
  Trace trace;
  TraceActivation active(trace);
  const TraceF x = TraceF::named("x");
  const TraceI i = TraceI::named("i");
  EXPECT_EQ((x - 0.0f).text, "x");
  EXPECT_EQ((x * 1.0f).text, "x");
  EXPECT_EQ((i + 0).text, "i");
  EXPECT_EQ((i & -1).text, "i");
  EXPECT_EQ(trace.statements(), 0);
  // x + 0 is -0 + 0 = +0 for x = -0, and x - (-0) is +0 too: both computed.
  EXPECT_NE((x + 0.0f).text, "x");
  EXPECT_NE((x - -0.0f).text, "x");
  EXPECT_EQ(trace.statements(), 2);
}

TEST(LaneTrace, RepeatedExpressionsReuseATemporaryInScope) {
  Trace trace;
  TraceActivation active(trace);
  const TraceF a = TraceF::named("a"), b = TraceF::named("b");
  const TraceF first = a * b;
  EXPECT_EQ((a * b).text, first.text);
  trace.open("if (c)");
  EXPECT_EQ((a * b).text, first.text);  // declared outside: in scope
  const TraceF inner = a / b;
  trace.close();
  EXPECT_NE((a / b).text, inner.text);  // declared inside: gone
  EXPECT_EQ(count_of(trace.text(), "float t"), 3);
}

TEST(LaneTrace, LiteralsReadBackExactly) {
  for (float value : {0.1f, 1.0f / 3.0f, 1e-30f, 3.4028235e38f, 16777217.0f, 1e-45f, 6.0f}) {
    const std::string text = glsl_float(value);
    EXPECT_EQ(std::strtof(text.c_str(), nullptr), value) << text;
    EXPECT_NE(text.find_first_of(".e"), std::string::npos) << text;
  }
  EXPECT_EQ(glsl_float(-2.5f), "(-2.5)");
  EXPECT_EQ(glsl_float(-0.0f), "(-0.0)");
  EXPECT_EQ(glsl_float(std::numeric_limits<float>::infinity()), "uintBitsToFloat(0x7f800000u)");
  EXPECT_EQ(glsl_float(std::nanf("")), "uintBitsToFloat(0x7fc00000u)");
  EXPECT_EQ(glsl_int(std::numeric_limits<std::int32_t>::min()), "(-2147483647 - 1)");
}

TEST(LaneTrace, TableLookupsNameTheirArray) {
  Trace trace;
  TraceActivation active(trace);
  const float table[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  trace.add_table(table, 8, "knots");
  EXPECT_EQ(gather(table + 2, TraceI(3)).value, 5.0f);  // a constant index reads the entry
  EXPECT_FALSE(trace.used("knots"));
  gather(table + 2, TraceI::named("k"));
  EXPECT_NE(trace.text().find("knots[k + 2]"), std::string::npos) << trace.text();
  EXPECT_TRUE(trace.used("knots"));
  const float elsewhere[2] = {};
  EXPECT_THROW(gather(elsewhere, TraceI::named("k")), std::logic_error);
}

TEST(LaneTrace, LoopWhileIsOneRolledLoop) {
  Trace trace;
  TraceActivation active(trace);
  const TraceF octaves = TraceF::named("octaves");
  TraceF sum;
  float scale = 1.0f;
  loop_while(
      16, [&](const TraceF& i, const TraceF&, const auto&) { return i < octaves; },
      [&](const TraceM& active, TraceF& sum, auto& scale) {
        sum = sum + select(active, scale, TraceF(0.0f));
        scale = scale * 0.5f;
      },
      sum, scale);
  const std::string& text = trace.text();
  EXPECT_EQ(count_of(text, "for ("), 1) << text;
  EXPECT_EQ(count_of(text, "< 16;"), 1) << text;
  EXPECT_EQ(count_of(text, "break;"), 1) << text;
  EXPECT_LT(trace.statements(), 16) << text;
  EXPECT_FALSE(sum.constant);  // the loop's variable, after it
  EXPECT_EQ(count_of(text, sum.text + " = "), 2) << text;  // declared, then assigned once a step
}

// States that trade values in a step keep both: the old value of one is
// copied before the other is assigned over it.
TEST(LaneTrace, LoopWhileStatesMayTradeValues) {
  Trace trace;
  TraceActivation active(trace);
  TraceF a = TraceF::named("a"), b = TraceF::named("b");
  loop_while(
      4, [&](const TraceF& i, const TraceF&, const TraceF&) { return i < TraceF::named("n"); },
      [&](const TraceM&, TraceF& a, TraceF& b) { std::swap(a, b); }, a, b);
  const std::string& text = trace.text();
  EXPECT_EQ(text.find(a.text + " = " + b.text + ";"), std::string::npos) << text;
  EXPECT_EQ(text.find(b.text + " = " + a.text + ";"), std::string::npos) << text;
  EXPECT_NE(text.find("float t"), std::string::npos) << text;
  EXPECT_NE(text.find(" = " + a.text + ";"), std::string::npos) << "a's old value copied:\n" << text;
  EXPECT_NE(text.find(" = " + b.text + ";"), std::string::npos) << "b's old value copied:\n" << text;
}

}  // namespace
}  // namespace shadetree::lanes
