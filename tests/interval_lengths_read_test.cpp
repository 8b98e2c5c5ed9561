// Which values an interval program keeps a length for: on a shape
// transfer function volume, the chain from normalize to sphere, and
// nothing the noise reads.
#include <gtest/gtest.h>

#include <string>

#include "ir/interval_lengths_read.h"
#include "support/gallery.h"

namespace shadetree {
namespace {

TEST(IntervalLengthsRead, TheChainFromNormalizeToSphereKeepsItsLengths) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/stf_bumps.json");
  ASSERT_TRUE(loaded) << loaded.error().message;
  const ShadeIR& ir = loaded->ir;
  const std::vector<char> read = interval_lengths_read(ir);
  ASSERT_EQ(read.size(), ir.code.size());
  const auto kept = [&](const std::string& node, OpId op) {
    for (std::size_t i = 0; i < ir.code.size(); ++i)
      if (ir.code[i].kind == IrOpKind::op && ir.code[i].op == op && ir.code[i].source == node) return read[i] != 0;
    ADD_FAILURE() << "no " << node;
    return false;
  };
  // sphere(x - normalize(field) * k): the sphere reads distorted's length,
  // the difference push's, the product direction's.
  EXPECT_TRUE(kept("distorted", OpId::sub));
  EXPECT_TRUE(kept("push", OpId::mul));
  EXPECT_TRUE(kept("direction", OpId::normalize));
  // normalize's length is 1 whatever its argument's; the noise reads no
  // lengths, nor does a scalar product.
  EXPECT_FALSE(kept("field", OpId::sub));
  EXPECT_FALSE(kept("shift", OpId::mul));
  EXPECT_FALSE(kept("noise_at", OpId::add));
  EXPECT_FALSE(kept("k", OpId::mul));
}

}  // namespace
}  // namespace shadetree
