// The if node's branches land in regions that run only where they are taken.
#include <gtest/gtest.h>

#include "pipeline/compile_graph.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

ShadeIR lower_text(const std::string& text) {
  Result<LoadedGraph> loaded = compile_graph_text(text, "g.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return loaded->ir;
}

// The region an instruction of a given source node sits in: 0 outside,
// 1 in the first region opened, and so on (-1 if absent).
int region_of(const ShadeIR& ir, const std::string& source) {
  int open = 0, opened = 0;
  std::vector<int> stack;
  for (const IrInstr& instr : ir.code) {
    if (instr.kind == IrOpKind::begin_region) {
      stack.push_back(++opened);
      continue;
    }
    if (instr.kind == IrOpKind::end_region) {
      stack.pop_back();
      continue;
    }
    open = stack.empty() ? 0 : stack.back();
    if (instr.source == source && instr.kind == IrOpKind::op) return open;
  }
  return -1;
}

const std::string branching_graph = testing::graph_text(
    R"({"id": "p", "op": "P"}, {"id": "x", "op": "split", "in": {"v": "p"}},
       {"id": "cond", "op": "lt", "in": {"a": "x.x", "b": 0.5}},
       {"id": "expensive", "op": "turbulence", "in": {"p": "p"}},
       {"id": "cheap", "op": "noise", "in": {"p": "p"}},
       {"id": "shared", "op": "abs", "in": {"x": "x.y"}},
       {"id": "then", "op": "add", "in": {"a": "expensive", "b": "shared"}},
       {"id": "else", "op": "sub", "in": {"a": "cheap", "b": "shared"}},
       {"id": "pick", "op": "if", "in": {"cond": "cond", "then": "then", "else": "else"}},
       {"id": "c", "op": "color", "in": {"r": "pick"}})",
    R"("color": "c")");

TEST(PlaceConditionalRegions, BranchOnlyValuesMoveIntoTheirRegion) {
  const ShadeIR ir = lower_text(branching_graph);
  EXPECT_EQ(region_of(ir, "expensive"), 1);
  EXPECT_EQ(region_of(ir, "then"), 1);
  EXPECT_EQ(region_of(ir, "cheap"), 2);
  EXPECT_EQ(region_of(ir, "else"), 2);
}

TEST(PlaceConditionalRegions, SharedValuesStayOutside) {
  const ShadeIR ir = lower_text(branching_graph);
  EXPECT_EQ(region_of(ir, "shared"), 0);
  EXPECT_EQ(region_of(ir, "cond"), 0);
  EXPECT_EQ(region_of(ir, "pick"), 0);
}

TEST(PlaceConditionalRegions, ArgumentsPrecedeTheirUsers) {
  const ShadeIR ir = lower_text(branching_graph);
  for (std::size_t i = 0; i < ir.code.size(); ++i)
    for (int a = 0; a < ir.code[i].arg_count; ++a) EXPECT_LT(ir.code[i].args[a], static_cast<int>(i));
}

TEST(PlaceConditionalRegions, RegionMarkersPointAtTheirEnd) {
  const ShadeIR ir = lower_text(branching_graph);
  int regions = 0;
  for (const IrInstr& instr : ir.code) {
    if (instr.kind != IrOpKind::begin_region) continue;
    ++regions;
    EXPECT_EQ(ir.code[instr.immediate[1]].kind, IrOpKind::end_region);
  }
  EXPECT_EQ(regions, 2);
}

}  // namespace
}  // namespace shadetree
