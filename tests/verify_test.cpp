// The ShadeIR verifier accepts what lowering and every pass produce for the
// gallery, and names the broken invariant in programs that break one.
#include <gtest/gtest.h>

#include "ir/verify.h"
#include "pipeline/compile_graph.h"
#include "support/gallery.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

TEST(Verify, GalleryIsWellFormedAfterEveryPass) {
  for (const std::string& file : testing::gallery_graphs()) {
    int passes = 0;
    Result<LoadedGraph> loaded = testing::load_gallery_graph(file, [&](const char* pass, const ShadeIR& ir) {
      EXPECT_EQ(verify_shade_ir(ir), "") << file << " after " << pass;
      ++passes;
    });
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    EXPECT_EQ(passes, 6) << file;  // lowering and five passes
  }
}

// A small program with a region: fbm only where P.x < 0.
ShadeIR program() {
  Result<LoadedGraph> loaded = compile_graph_text(testing::graph_text(
      R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}},
         {"id": "c", "op": "lt", "in": {"a": "s.x", "b": 0}},
         {"id": "f", "op": "fbm", "in": {"p": "p"}},
         {"id": "k", "op": "if", "in": {"cond": "c", "then": "f", "else": 1}})",
      R"("color": "k")"), "g.json");
  EXPECT_TRUE(loaded.ok());
  EXPECT_EQ(verify_shade_ir(loaded->ir), "");
  return loaded->ir;
}

std::size_t find(const ShadeIR& ir, IrOpKind kind, OpId op = OpId::add) {
  for (std::size_t i = 0; i < ir.code.size(); ++i)
    if (ir.code[i].kind == kind && (kind != IrOpKind::op || ir.code[i].op == op)) return i;
  return 0;
}

TEST(Verify, OperandsMustPrecedeTheirUsers) {
  ShadeIR ir = program();
  IrInstr& fbm = ir.code[find(ir, IrOpKind::op, OpId::fbm)];
  fbm.args[0] = static_cast<std::int32_t>(ir.code.size() - 1);
  EXPECT_NE(verify_shade_ir(ir).find("does not precede its user"), std::string::npos) << verify_shade_ir(ir);
}

TEST(Verify, ArgumentsMustHaveTheSignaturesTypes) {
  ShadeIR ir = program();
  const std::size_t lt = find(ir, IrOpKind::op, OpId::lt);
  IrInstr& fbm = ir.code[find(ir, IrOpKind::op, OpId::fbm)];
  fbm.type = Type::vec3;
  EXPECT_EQ(verify_shade_ir(ir).substr(verify_shade_ir(ir).find(' ') + 1), "fbm returns float, typed vec3");
  fbm.type = Type::float_;
  ir.code[lt].arg_count = 1;
  EXPECT_NE(verify_shade_ir(ir).find("lt takes 2 arguments, has 1"), std::string::npos);
}

TEST(Verify, RegionsMustBeWellNested) {
  ShadeIR ir = program();
  const std::size_t begin = find(ir, IrOpKind::begin_region);
  ASSERT_GT(begin, 0u);
  ir.code[begin].immediate[1] += 1;
  EXPECT_NE(verify_shade_ir(ir).find("region ends at"), std::string::npos) << verify_shade_ir(ir);
  ir = program();
  ir.code.erase(ir.code.begin() + static_cast<std::ptrdiff_t>(find(ir, IrOpKind::end_region)));
  EXPECT_NE(verify_shade_ir(ir), "");
}

TEST(Verify, UniformCodeReadsOnlyUniformValues) {
  ShadeIR ir = program();
  ir.code[find(ir, IrOpKind::op, OpId::lt)].uniform = true;
  EXPECT_NE(verify_shade_ir(ir).find("uniform, but reads the varying"), std::string::npos) << verify_shade_ir(ir);
}

TEST(Verify, OutputsFollowTheContract) {
  ShadeIR ir = program();
  ir.outputs[0].type = Type::float_;
  EXPECT_EQ(verify_shade_ir(ir), "output color has the wrong type");
  ir = program();
  ir.outputs[0].id = OutputId::density;
  EXPECT_EQ(verify_shade_ir(ir), "output density is not (in this order) in the contract of texture graphs");
}

}  // namespace
}  // namespace shadetree
