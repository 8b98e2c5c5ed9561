// Constant folding replaces constant computations by their values, exactly
// as the interpreter computes them, and leaves params and inputs alone.
#include <gtest/gtest.h>

#include "pipeline/compile_graph.h"
#include "nodes/noise_tables.h"
#include "nodes/semantics/arithmetic.h"
#include "nodes/semantics/noise.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

int count_ops(const ShadeIR& ir) {
  int ops = 0;
  for (const IrInstr& instr : ir.code) ops += instr.kind == IrOpKind::op;
  return ops;
}

TEST(FoldConstants, FoldsConstantChainsToTheirValue) {
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(
      R"({"id": "g", "op": "gain", "in": {"t": 0.25, "g": 0.8}},
         {"id": "n", "op": "noise", "in": {"p": [0.3, 0.6, 0.9]}},
         {"id": "sum", "op": "add", "in": {"a": "g", "b": "n"}},
         {"id": "c", "op": "color", "in": {"r": "sum", "g": "g"}})",
      R"("color": "c")"), "g.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const ShadeIR& ir = loaded->ir;
  EXPECT_EQ(count_ops(ir), 0) << format_shade_ir(ir);
  const IrInstr& color = ir.code[ir.outputs[0].value];
  ASSERT_EQ(color.kind, IrOpKind::constant);
  const float expected_gain = semantics::gain(0.25f, 0.8f);
  const float expected_noise = semantics::noise(noise_tables(default_noise_seed), 0.3f, 0.6f, 0.9f);
  EXPECT_EQ(ir.data[color.data_offset], expected_gain + expected_noise);
  EXPECT_EQ(ir.data[color.data_offset + 1], expected_gain);
  EXPECT_EQ(ir.data[color.data_offset + 2], 0.0f);
}

TEST(FoldConstants, KeepsParamsAndInputsVarying) {
  const std::string params = R"("params": {"k": {"type": "float", "default": 2}},)";
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(
      R"({"id": "t", "op": "time"}, {"id": "a", "op": "mul", "in": {"a": "$k", "b": 3}},
         {"id": "b", "op": "add", "in": {"a": "a", "b": "t"}},
         {"id": "c", "op": "color", "in": {"r": "b"}})",
      R"("color": "c")", params), "g.json");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(count_ops(loaded->ir), 3) << format_shade_ir(loaded->ir);  // mul, add, color (and the global time)
  for (const IrInstr& instr : loaded->ir.code) EXPECT_TRUE(instr.uniform) << format_shade_ir(loaded->ir);
}

}  // namespace
}  // namespace shadetree
