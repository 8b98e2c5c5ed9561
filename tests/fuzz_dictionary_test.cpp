// The fuzzer's dictionary (fuzz/graph.dict) names every op of the library,
// so that a new op is fuzzed from the start.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "nodes/registry.h"

namespace shadetree {
namespace {

TEST(FuzzDictionary, NamesEveryOp) {
  std::ifstream file(SHADETREE_SOURCE_DIR "/fuzz/graph.dict");
  ASSERT_TRUE(file) << "fuzz/graph.dict is missing";
  std::stringstream text;
  text << file.rdbuf();
  for (const OpDef& op : all_ops())
    EXPECT_NE(text.str().find("\"\\\"" + op.name + "\\\"\""), std::string::npos) << op.name << " is not in fuzz/graph.dict";
}

}  // namespace
}  // namespace shadetree
