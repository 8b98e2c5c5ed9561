// The interpreter evaluates graphs as the semantics define them, block by
// block, inside and outside conditional regions.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/compile_graph.h"
#include "interp/interpreter.h"
#include "nodes/semantics/arithmetic.h"
#include "nodes/semantics/noise.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

struct Evaluation {
  std::vector<float> px, py, pz, color[3];
};

// Evaluates a texture graph's color at `count` points along a line.
Evaluation evaluate(const std::string& text, std::size_t count) {
  Result<LoadedGraph> loaded = compile_graph_text(text, "g.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  ShadeIR ir = loaded->ir;
  const std::vector<float> params = loaded->params;
  Evaluation result;
  for (std::size_t i = 0; i < count; ++i) {
    result.px.push_back(-3.0f + 0.0137f * static_cast<float>(i));
    result.py.push_back(0.5f + 0.003f * static_cast<float>(i));
    result.pz.push_back(0.25f);
  }
  for (auto& plane : result.color) plane.assign(count, -1.0f);
  SampleInputs inputs;
  inputs.planes[global_def(GlobalId::P).first] = result.px.data();
  inputs.planes[global_def(GlobalId::P).first + 1] = result.py.data();
  inputs.planes[global_def(GlobalId::P).first + 2] = result.pz.data();
  float* outputs[4] = {result.color[0].data(), result.color[1].data(), result.color[2].data(), nullptr};
  make_interpreted_kernel(std::move(ir))->bind(params.data(), UniformInputs{})->run(inputs, outputs, count);
  return result;
}

TEST(Interpreter, EvaluatesNoiseAcrossBlocksAndTheTail) {
  const std::size_t count = 3 * interpreter_block_size + 17;
  const Evaluation result = evaluate(testing::graph_text(R"({"id": "p", "op": "P"},
      {"id": "n", "op": "noise", "in": {"p": "p"}}, {"id": "c", "op": "color", "in": {"r": "n", "g": 2}})",
                                                         R"("color": "c")"),
                                     count);
  const NoiseTables& tables = noise_tables(default_noise_seed);
  for (std::size_t i = 0; i < count; ++i) {
    ASSERT_EQ(result.color[0][i], semantics::noise(tables, result.px[i], result.py[i], result.pz[i])) << i;
    ASSERT_EQ(result.color[1][i], 2.0f) << i;
    ASSERT_EQ(result.color[2][i], 0.0f) << i;
  }
}

TEST(Interpreter, IfTakesEachBranchWhereItsConditionSays) {
  const std::size_t count = interpreter_block_size + 40;
  const Evaluation result = evaluate(testing::graph_text(R"({"id": "p", "op": "P"},
      {"id": "x", "op": "split", "in": {"v": "p"}},
      {"id": "cond", "op": "lt", "in": {"a": "x.x", "b": -1.0}},
      {"id": "a", "op": "mul", "in": {"a": "x.x", "b": 10}},
      {"id": "b", "op": "sqrt", "in": {"x": "x.x"}},
      {"id": "pick", "op": "if", "in": {"cond": "cond", "then": "a", "else": "b"}},
      {"id": "c", "op": "color", "in": {"r": "pick"}})",
                                                         R"("color": "c")"),
                                     count);
  for (std::size_t i = 0; i < count; ++i) {
    const float x = result.px[i];
    if (x < -1.0f) {
      ASSERT_EQ(result.color[0][i], x * 10.0f) << i;
    } else if (x >= 0.0f) {
      ASSERT_EQ(result.color[0][i], std::sqrt(x)) << i;
    } else {
      ASSERT_TRUE(std::isnan(result.color[0][i])) << i;  // sqrt of a negative, as asked
    }
  }
}

// Regression: an `if` inside an `if` on the same condition opened a second
// lane list while the first still pointed into the storage it grew
// (a use-after-free under AddressSanitizer, wrong values or a crash in
// release builds).
TEST(Interpreter, NestedIfsOnOneConditionKeepTheirLaneLists) {
  const std::size_t count = 2 * interpreter_block_size + 9;
  const Evaluation result = evaluate(testing::graph_text(R"({"id": "p", "op": "P"},
      {"id": "x", "op": "split", "in": {"v": "p"}},
      {"id": "c", "op": "lt", "in": {"a": "x.x", "b": 1}},
      {"id": "n", "op": "sin", "in": {"x": "x.x"}},
      {"id": "inner", "op": "if", "in": {"cond": "c", "then": "n", "else": 0}},
      {"id": "outer", "op": "if", "in": {"cond": "c", "then": "inner", "else": 1}},
      {"id": "out", "op": "color", "in": {"r": "outer"}})",
                                                         R"("color": "out")"),
                                     count);
  for (std::size_t i = 0; i < count; ++i) {
    const float x = result.px[i];
    ASSERT_EQ(result.color[0][i], x < 1.0f ? semantics::sine(x) : 1.0f) << i;
  }
}

TEST(Interpreter, DeepChainsOfNestedIfsRun) {
  constexpr int depth = 300;
  std::string nodes = R"({"id": "p", "op": "P"}, {"id": "x", "op": "split", "in": {"v": "p"}},
      {"id": "c", "op": "lt", "in": {"a": "x.x", "b": 0}}, {"id": "v0", "op": "neg", "in": {"x": "x.x"}})";
  for (int k = 1; k <= depth; ++k)
    nodes += R"(, {"id": "v)" + std::to_string(k) + R"(", "op": "if", "in": {"cond": "c", "then": "v)" +
             std::to_string(k - 1) + R"(", "else": )" + std::to_string(k) + "}}";
  nodes += R"(, {"id": "out", "op": "color", "in": {"r": "v)" + std::to_string(depth) + R"("}})";
  const std::size_t count = interpreter_block_size + 3;
  const Evaluation result = evaluate(testing::graph_text(nodes, R"("color": "out")"), count);
  for (std::size_t i = 0; i < count; ++i)
    ASSERT_EQ(result.color[0][i], result.px[i] < 0.0f ? -result.px[i] : static_cast<float>(depth)) << i;
}

// Regression: dot(1, v) read the scalar as a one-component vector and
// returned v.x instead of v.x + v.y + v.z.
TEST(Interpreter, ScalarArgumentsOfVectorOpsAreSplatToT) {
  const Evaluation result = evaluate(testing::graph_text(R"({"id": "v", "op": "vec3", "in": {"x": 1, "y": 2, "z": 3}},
      {"id": "d", "op": "dot", "in": {"a": 1, "b": "v"}},
      {"id": "e", "op": "dot", "in": {"a": "v", "b": 2}},
      {"id": "c", "op": "color", "in": {"r": "d", "g": "e"}})",
                                                         R"("color": "c")"),
                                     1);
  EXPECT_EQ(result.color[0][0], 6.0f);
  EXPECT_EQ(result.color[1][0], 12.0f);
}

TEST(Interpreter, ParamsAreReadFromTheUniformBlock) {
  const std::string params = R"("params": {"k": {"type": "color", "default": [0.25, 0.5, 0.75]}},)";
  const Evaluation result = evaluate(
      testing::graph_text(R"({"id": "c", "op": "mul", "in": {"a": "$k", "b": 2}})", R"("color": "c")", params), 5);
  EXPECT_EQ(result.color[0][4], 0.5f);
  EXPECT_EQ(result.color[1][4], 1.0f);
  EXPECT_EQ(result.color[2][4], 1.5f);
}

TEST(Interpreter, InlinesFunctions) {
  const std::string functions = R"("functions": {"twice": {"inputs": {"x": "float"},
      "nodes": [{"id": "d", "op": "mul", "in": {"a": "$x", "b": 2}}], "outputs": {"y": "d"}}},)";
  const Evaluation result = evaluate(testing::graph_text(R"({"id": "p", "op": "P"},
      {"id": "s", "op": "split", "in": {"v": "p"}}, {"id": "t", "op": "twice", "in": {"x": "s.y"}},
      {"id": "c", "op": "color", "in": {"r": "t", "g": "s.z", "b": "s.x"}})",
                                                         R"("color": "c")", functions),
                                     10);
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(result.color[0][i], result.py[i] * 2.0f);
    EXPECT_EQ(result.color[1][i], 0.25f);
    EXPECT_EQ(result.color[2][i], result.px[i]);
  }
}

TEST(Interpreter, SplitOfVec2HasZeroZ) {
  const Evaluation result = evaluate(testing::graph_text(R"({"id": "v", "op": "vec2", "in": {"x": 3, "y": 4}},
      {"id": "s", "op": "split", "in": {"v": "v"}}, {"id": "l", "op": "length", "in": {"v": "v"}},
      {"id": "c", "op": "color", "in": {"r": "s.y", "g": "s.z", "b": "l"}})",
                                                         R"("color": "c")"),
                                     3);
  EXPECT_EQ(result.color[0][0], 4.0f);
  EXPECT_EQ(result.color[1][0], 0.0f);
  EXPECT_EQ(result.color[2][0], 5.0f);
}

}  // namespace
}  // namespace shadetree
