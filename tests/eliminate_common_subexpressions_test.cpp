// Common subexpression elimination merges repeated pure computations,
// including those that functions repeat when inlined twice.
#include <gtest/gtest.h>

#include "pipeline/compile_graph.h"
#include "nodes/registry.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

int count_op(const ShadeIR& ir, OpId op) {
  int count = 0;
  for (const IrInstr& instr : ir.code)
    count += (instr.kind == IrOpKind::op || instr.kind == IrOpKind::global) && instr.op == op;
  return count;
}

TEST(EliminateCommonSubexpressions, MergesRepeatedNodesAndInlinedFunctions) {
  const std::string functions = R"("functions": {"wave": {"inputs": {"x": "float"},
      "nodes": [{"id": "n", "op": "turbulence", "in": {"p": "P"}}, {"id": "P", "op": "P"},
                {"id": "s", "op": "add", "in": {"a": "n", "b": "$x"}}], "outputs": {"y": "s"}}},)";
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(
      R"({"id": "p", "op": "P"}, {"id": "n1", "op": "noise", "in": {"p": "p"}},
         {"id": "n2", "op": "noise", "in": {"p": "p"}},
         {"id": "w1", "op": "wave", "in": {"x": "n1"}}, {"id": "w2", "op": "wave", "in": {"x": "n2"}},
         {"id": "c", "op": "color", "in": {"r": "w1", "g": "w2"}})",
      R"("color": "c")", functions), "g.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(count_op(loaded->ir, OpId::noise), 1) << format_shade_ir(loaded->ir);
  EXPECT_EQ(count_op(loaded->ir, OpId::turbulence), 1);
  EXPECT_EQ(count_op(loaded->ir, OpId::add), 1);
  EXPECT_EQ(count_op(loaded->ir, OpId::P), 1);
  EXPECT_LT(static_cast<int>(loaded->ir.code.size()), loaded->instructions_before_optimization);
}

TEST(EliminateCommonSubexpressions, KeepsNodesThatDifferInSeedOrData) {
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(
      R"({"id": "p", "op": "P"}, {"id": "n1", "op": "noise", "in": {"p": "p"}, "seed": 1},
         {"id": "n2", "op": "noise", "in": {"p": "p"}, "seed": 2},
         {"id": "s1", "op": "spline", "in": {"x": "n1"}, "basis": "linear", "knots": [0, 1]},
         {"id": "s2", "op": "spline", "in": {"x": "n1"}, "basis": "linear", "knots": [0, 2]},
         {"id": "c", "op": "color", "in": {"r": "n2", "g": "s1", "b": "s2"}})",
      R"("color": "c")"), "g.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(count_op(loaded->ir, OpId::noise), 2);
  EXPECT_EQ(count_op(loaded->ir, OpId::spline), 2);
}

}  // namespace
}  // namespace shadetree
