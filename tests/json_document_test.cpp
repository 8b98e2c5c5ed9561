// Graph files as JSON documents (graph/json_document.h): the same
// document nlohmann builds, in file order, in linear time; a key written
// twice and nesting past the limit are refused with one line.
#include "graph/json_document.h"

#include <gtest/gtest.h>

#include "graph/parse.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

TEST(JsonDocument, KeepsMembersInFileOrderAndEveryValueType) {
  const std::string text = R"({"z": 1, "a": [true, null, -2, 18446744073709551615, 0.5, "s"], "m": {"y": {}, "b": []}})";
  Result<json> document = parse_json_document(text, "d.json");
  ASSERT_TRUE(document.ok()) << document.error().to_string();
  EXPECT_EQ(*document, json::parse(text));
  EXPECT_EQ(document->begin().key(), "z");
  EXPECT_EQ((*document)["m"].begin().key(), "y");
}

TEST(JsonDocument, SyntaxErrorsNameTheLineAndColumn) {
  Result<json> document = parse_json_document("{\n  \"a\": [1, 2,]\n}", "d.json");
  ASSERT_FALSE(document.ok());
  EXPECT_EQ(document.error().file, "d.json");
  EXPECT_EQ(document.error().message.rfind("invalid JSON: parse error at line 2, column 14: syntax error", 0), 0u)
      << document.error().message;
  EXPECT_FALSE(parse_json_document("[1e400]", "d.json").ok());
  EXPECT_FALSE(parse_json_document("", "d.json").ok());
  EXPECT_FALSE(parse_json_document("{} {}", "d.json").ok());
}

// Issue 21: duplicate keys were accepted silently, the last one winning.
TEST(JsonDocument, RefusesAKeyWrittenTwiceInOneObject) {
  Result<json> document = parse_json_document(R"({"params": {"a": 1, "b": 2, "a": 3}})", "d.json");
  ASSERT_FALSE(document.ok());
  EXPECT_EQ(document.error().to_string(), "error: d.json: key \"a\" appears twice in one object");
  EXPECT_TRUE(parse_json_document(R"({"a": {"a": 1}, "b": [{"a": 1}, {"a": 2}]})", "d.json").ok());
}

TEST(JsonDocument, RefusesNestingPastTheLimitWithoutRecursion) {
  EXPECT_TRUE(parse_json_document(std::string(max_json_depth, '[') + std::string(max_json_depth, ']'), "d.json").ok());
  Result<json> deep = parse_json_document(std::string(1000000, '[') + std::string(1000000, ']'), "d.json");
  ASSERT_FALSE(deep.ok());
  EXPECT_EQ(deep.error().message, "JSON nested deeper than 64 levels");
}

// Issue 21: ordered_json built an object of n members in n^2 time (200k
// params took 53 s; 1.78 M keys in a 16 MiB file did not finish in 100 s).
// A million members parse; the graph parser reaches its own limits.
TEST(JsonDocument, AMillionMembersParse) {
  std::string text = "{";
  for (int i = 0; i < 1000000; ++i) text += (i ? ",\"k" : "\"k") + std::to_string(i) + "\":" + std::to_string(i % 10);
  text += "}";
  Result<json> document = parse_json_document(text, "d.json");
  ASSERT_TRUE(document.ok()) << document.error().to_string();
  EXPECT_EQ(document->size(), 1000000u);
  EXPECT_EQ((*document)["k999999"], 9);
}

TEST(JsonDocument, GraphsWithDuplicateKeysAreRefusedByTheParser) {
  Result<Graph> graph = parse_graph(
      testing::graph_text(R"({"id": "n", "op": "noise", "op": "turbulence"})", R"("color": "n")"), "g.json");
  ASSERT_FALSE(graph.ok());
  EXPECT_EQ(graph.error().to_string(), "error: g.json: key \"op\" appears twice in one object");
}

}  // namespace
}  // namespace shadetree
