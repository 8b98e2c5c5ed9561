// Differentiation (ir/differentiate.h) and the gradient and bump nodes:
// gradients against closed forms and the analytic Dnoise, on both
// backends and every vector width; only what depends on P is made dual;
// bump is Blinn's perturbed normal.
#include <gtest/gtest.h>

#include <cmath>

#include "interp/interpreter.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"
#include "support/differential_samples.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

using testing::SampleSet;
using testing::samples;

// A texture graph of `nodes` whose colour is node "out", with a param k = 0.5.
LoadedGraph compile(const std::string& nodes) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(nodes, R"("color": "out")", R"("params": {"k": {"type": "float", "default": 0.5}},)"),
      "gradient.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return std::move(*loaded);
}

// The colour output over the sample set, per backend: the interpreter,
// then the JIT at widths 4, 8 and 16. colour[backend][c][i].
std::vector<std::vector<std::vector<float>>> colour_on_every_backend(const LoadedGraph& graph) {
  std::vector<std::vector<std::vector<float>>> colours;
  for (const auto& kernel : testing::kernels_on_every_backend(graph.ir)) {
    auto planes = testing::run(*kernel, graph.params);
    const int first = kernel->outputs().plane(OutputId::color);
    colours.push_back({planes[first], planes[first + 1], planes[first + 2]});
  }
  return colours;
}

int dual_instructions(const ShadeIR& ir) {
  int count = 0;
  for (const IrInstr& instr : ir.code) count += instr.dual;
  return count;
}

TEST(Differentiate, TheGradientOfALinearFieldIsItsCoefficients) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"},
    {"id": "x", "op": "dot", "in": {"a": "p", "b": [1.5, -2, 0.25]}},
    {"id": "shifted", "op": "add", "in": {"a": "x", "b": 5}},
    {"id": "g", "op": "gradient", "in": {"x": "shifted"}}, {"id": "out", "op": "to_color", "in": {"v": "g"}})");
  for (const auto& colour : colour_on_every_backend(graph))
    for (std::size_t i = 0; i < SampleSet::count; ++i) {
      EXPECT_EQ(colour[0][i], 1.5f);
      EXPECT_EQ(colour[1][i], -2.0f);
      EXPECT_EQ(colour[2][i], 0.25f);
    }
}

// Perlin 1985's Dnoise is the analytic gradient of noise; the dual numbers
// run through noise's own lane form, so the two differ by rounding only.
// The chain rule brings the frequency out: grad noise(3 P) = 3 Dnoise(3 P).
TEST(Differentiate, TheGradientOfNoiseIsDnoiseOnEveryBackend) {
  const LoadedGraph gradient = compile(R"({"id": "p", "op": "P"},
    {"id": "q", "op": "mul", "in": {"a": "p", "b": 3}}, {"id": "n", "op": "noise", "in": {"p": "q"}},
    {"id": "g", "op": "gradient", "in": {"x": "n"}}, {"id": "out", "op": "to_color", "in": {"v": "g"}})");
  const LoadedGraph analytic = compile(R"({"id": "p", "op": "P"},
    {"id": "q", "op": "mul", "in": {"a": "p", "b": 3}}, {"id": "d", "op": "dnoise", "in": {"p": "q"}},
    {"id": "g", "op": "mul", "in": {"a": "d", "b": 3}}, {"id": "out", "op": "to_color", "in": {"v": "g"}})");
  const auto expected = colour_on_every_backend(analytic)[0];
  for (const auto& colour : colour_on_every_backend(gradient))
    for (int c = 0; c < 3; ++c)
      for (std::size_t i = 0; i < SampleSet::count; ++i) EXPECT_NEAR(colour[c][i], expected[c][i], 2e-5f) << i;
}

// The JIT runs the same dual semantics as the interpreter, operation for
// operation, so gradients agree bit for bit, as values do.
TEST(Differentiate, BackendsAgreeBitForBitOnTurbulenceThroughAConditional) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
    {"id": "t", "op": "turbulence", "in": {"p": "p", "octaves": 5}},
    {"id": "far", "op": "gt", "in": {"a": "s.x", "b": 0}},
    {"id": "bent", "op": "pow", "in": {"a": "t", "b": 1.7}},
    {"id": "h", "op": "if", "in": {"cond": "far", "then": "bent", "else": "t"}},
    {"id": "g", "op": "gradient", "in": {"x": "h"}}, {"id": "out", "op": "to_color", "in": {"v": "g"}})");
  const auto colours = colour_on_every_backend(graph);
  for (std::size_t backend = 1; backend < colours.size(); ++backend) EXPECT_EQ(colours[backend], colours[0]);
}

// where x < 0: h = x^2 sin y, so grad h = (2 x sin y, x^2 cos y, 0);
// elsewhere h = exp(z), grad h = (0, 0, exp z).
TEST(Differentiate, TheChainRuleRunsThroughEachBranchOfAnIf) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
    {"id": "x2", "op": "mul", "in": {"a": "s.x", "b": "s.x"}}, {"id": "sy", "op": "sin", "in": {"x": "s.y"}},
    {"id": "left", "op": "mul", "in": {"a": "x2", "b": "sy"}}, {"id": "right", "op": "exp", "in": {"x": "s.z"}},
    {"id": "neg", "op": "lt", "in": {"a": "s.x", "b": 0}},
    {"id": "h", "op": "if", "in": {"cond": "neg", "then": "left", "else": "right"}},
    {"id": "g", "op": "gradient", "in": {"x": "h"}}, {"id": "out", "op": "to_color", "in": {"v": "g"}})");
  for (const auto& colour : colour_on_every_backend(graph))
    for (std::size_t i = 0; i < SampleSet::count; ++i) {
      const double x = samples().P(0, i), y = samples().P(1, i), z = samples().P(2, i);
      if (std::fabs(z) > 80) continue;  // exp overflows
      const double expected[3] = {x < 0 ? 2 * x * std::sin(y) : 0.0, x < 0 ? x * x * std::cos(y) : 0.0,
                                  x < 0 ? 0.0 : std::exp(z)};
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(colour[c][i], expected[c], 1e-5 * std::max(1.0, std::fabs(expected[c]))) << i << " " << c;
    }
}

// Params, N and uv do not depend on P: their gradient is a zero constant,
// and nothing is made dual for it.
TEST(Differentiate, WhatDoesNotDependOnPHasAZeroGradientAndNoDualCode) {
  const LoadedGraph graph = compile(R"({"id": "n", "op": "N"}, {"id": "uv", "op": "uv"},
    {"id": "s", "op": "split", "in": {"v": "uv"}}, {"id": "t", "op": "split", "in": {"v": "n"}},
    {"id": "h", "op": "mul", "in": {"a": "t.x", "b": "s.y"}}, {"id": "k", "op": "mul", "in": {"a": "h", "b": "$k"}},
    {"id": "g", "op": "gradient", "in": {"x": "k"}}, {"id": "out", "op": "to_color", "in": {"v": "g"}})");
  EXPECT_EQ(dual_instructions(graph.ir), 0) << format_shade_ir(graph.ir);
  for (const auto& colour : colour_on_every_backend(graph))
    for (int c = 0; c < 3; ++c)
      for (float value : colour[c]) EXPECT_EQ(value, 0.0f);
}

// h = noise(P) k + N.x: P, noise, the product and the sum are dual; N, its
// component and the param k are read as they are.
TEST(Differentiate, OnlyTheValuesThatDependOnPAreMadeDual) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"}, {"id": "n", "op": "N"},
    {"id": "t", "op": "split", "in": {"v": "n"}}, {"id": "noise", "op": "noise", "in": {"p": "p"}},
    {"id": "scaled", "op": "mul", "in": {"a": "noise", "b": "$k"}},
    {"id": "h", "op": "add", "in": {"a": "scaled", "b": "t.x"}},
    {"id": "g", "op": "gradient", "in": {"x": "h"}}, {"id": "out", "op": "to_color", "in": {"v": "g"}})");
  EXPECT_EQ(dual_instructions(graph.ir), 4) << format_shade_ir(graph.ir);
  for (const IrInstr& instr : graph.ir.code)
    if (instr.dual) EXPECT_TRUE(instr.kind == IrOpKind::global || instr.kind == IrOpKind::op) << instr.source;
}

// Two gradients of one height share its dual code.
TEST(Differentiate, GradientsOfOneValueShareTheirDualCode) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"}, {"id": "h", "op": "turbulence", "in": {"p": "p"}},
    {"id": "g1", "op": "gradient", "in": {"x": "h"}}, {"id": "g2", "op": "gradient", "in": {"x": "h"}},
    {"id": "sum", "op": "add", "in": {"a": "g1", "b": "g2"}}, {"id": "out", "op": "to_color", "in": {"v": "sum"}})");
  EXPECT_EQ(dual_instructions(graph.ir), 2) << format_shade_ir(graph.ir);
}

// Blinn 1978: normalize(N - s (g - (g . N) N)), with N made unit first;
// here g = (0.3, -0.2, 0.1) everywhere, the samples' N random unit vectors.
TEST(Differentiate, BumpIsBlinnsPerturbedNormal) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"}, {"id": "n", "op": "N"},
    {"id": "h", "op": "dot", "in": {"a": "p", "b": [0.3, -0.2, 0.1]}},
    {"id": "twice", "op": "mul", "in": {"a": "n", "b": 2}},
    {"id": "b", "op": "bump", "in": {"height": "h", "normal": "twice", "strength": 1.5}},
    {"id": "out", "op": "to_color", "in": {"v": "b"}})");
  const double g[3] = {0.3, -0.2, 0.1};
  for (const auto& colour : colour_on_every_backend(graph))
    for (std::size_t i = 0; i < SampleSet::count; ++i) {
      double n[3], along = 0, bent[3], length = 0;
      for (int c = 0; c < 3; ++c) n[c] = samples().input.inputs().plane(GlobalId::N, c)[i];
      for (int c = 0; c < 3; ++c) along += g[c] * n[c];
      for (int c = 0; c < 3; ++c) length += (bent[c] = n[c] - 1.5 * (g[c] - along * n[c])) * bent[c];
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(colour[c][i], bent[c] / std::sqrt(length), 1e-6) << i;
    }
}

// A flat height leaves the normal as it is (made unit).
TEST(Differentiate, BumpOfAConstantHeightIsTheUnitNormal) {
  const LoadedGraph graph = compile(R"({"id": "b", "op": "bump", "in": {"height": 0.7, "normal": [0, 0, 3]}},
    {"id": "out", "op": "to_color", "in": {"v": "b"}})");
  for (const auto& colour : colour_on_every_backend(graph))
    for (std::size_t i = 0; i < SampleSet::count; ++i) {
      EXPECT_EQ(colour[0][i], 0.0f);
      EXPECT_EQ(colour[1][i], 0.0f);
      EXPECT_EQ(colour[2][i], 1.0f);
    }
}

}  // namespace
}  // namespace shadetree
