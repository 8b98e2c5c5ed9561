// Lowering (ir/lower.h) of the nodes that become more than one
// instruction: vnoise is three noises of its node's seed at p - sigma, p
// and p + sigma, to the bit on both backends.
#include <gtest/gtest.h>

#include "nodes/ops/generators.h"
#include "pipeline/compile_graph.h"
#include "support/differential_samples.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

using testing::SampleSet;
using testing::samples;

LoadedGraph compile(const std::string& nodes) {
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(nodes, R"("color": "out")"), "lower.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return std::move(*loaded);
}

int count_of(const ShadeIR& ir, OpId op) {
  int count = 0;
  for (const IrInstr& instr : ir.code) count += instr.kind == IrOpKind::op && instr.op == op;
  return count;
}

TEST(Lower, VnoiseIsThreeNoisesOfItsSeedAtPMinusSigmaPAndPPlusSigma) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"},
    {"id": "v", "op": "vnoise", "in": {"p": "p"}, "seed": 7},
    {"id": "out", "op": "to_color", "in": {"v": "v"}})");
  EXPECT_EQ(count_of(graph.ir, OpId::vnoise), 0);
  EXPECT_EQ(count_of(graph.ir, OpId::noise), 3);

  const NoiseTables& tables = noise_tables(7);
  const float* sigma = ops::vnoise::offset;
  for (const auto& kernel : testing::kernels_on_every_backend(graph.ir)) {
    const auto planes = testing::run(*kernel, graph.params);
    const int colour = kernel->outputs().plane(OutputId::color);
    for (std::size_t i = 0; i < SampleSet::count; ++i) {
      float p[3];
      for (int c = 0; c < 3; ++c) p[c] = samples().input.inputs().plane(GlobalId::P, c)[i];
      EXPECT_EQ(planes[colour][i], semantics::noise(tables, p[0] - sigma[0], p[1] - sigma[1], p[2] - sigma[2])) << i;
      EXPECT_EQ(planes[colour + 1][i], semantics::noise(tables, p[0], p[1], p[2])) << i;
      EXPECT_EQ(planes[colour + 2][i], semantics::noise(tables, p[0] + sigma[0], p[1] + sigma[1], p[2] + sigma[2])) << i;
    }
  }
}

// A graph's plain noise at p and its vnoise's middle noise are one value.
TEST(Lower, ANoiseAtTheSamePointIsSharedWithVnoise) {
  const LoadedGraph graph = compile(R"({"id": "p", "op": "P"},
    {"id": "v", "op": "vnoise", "in": {"p": "p"}},
    {"id": "n", "op": "noise", "in": {"p": "p"}},
    {"id": "sum", "op": "add", "in": {"a": "v", "b": "n"}},
    {"id": "out", "op": "to_color", "in": {"v": "sum"}})");
  EXPECT_EQ(count_of(graph.ir, OpId::noise), 3);
}

}  // namespace
}  // namespace shadetree
