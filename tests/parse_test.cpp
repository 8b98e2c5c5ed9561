// Reading a graph file (graph/parse.h, load_graph): whatever its length,
// a file is read whole up to the limit and refused one byte past it,
// without reading more of it than that.
#include "graph/parse.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/graph_text.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

TEST(LoadGraph, ReadsAFileOfManyChunksWhole) {
  const testing::TempFolder folder("shadetree-load-graph");
  // A doc of 1 MiB + 3 bytes: the file ends neither on nor near a chunk's edge.
  const std::string doc((1u << 20) + 3, 'd');
  const std::string path = folder.write("long.json", testing::graph_text(R"({"id": "x", "op": "P"})", R"("color": "x")",
                                                                    R"("doc": ")" + doc + R"(",)"));
  Result<Graph> graph = load_graph(path);
  ASSERT_TRUE(graph) << graph.error().message;
  EXPECT_EQ(graph->doc, doc);
  EXPECT_EQ(graph->nodes.size(), 1u);
}

TEST(LoadGraph, RefusesAFileOverTheLimitHoweverLarge) {
  const testing::TempFolder folder("shadetree-load-graph");
  // One byte over, and a sparse file of 64 GiB, which is never read past the limit.
  for (const std::uintmax_t size : {std::uintmax_t{max_graph_file_bytes} + 1, std::uintmax_t{64} << 30}) {
    const std::string path = folder.write("big.json", testing::graph_text("", ""));
    std::filesystem::resize_file(path, size);
    Result<Graph> graph = load_graph(path);
    ASSERT_FALSE(graph) << size;
    EXPECT_EQ(graph.error().status, ExitStatus::invalid_input);
    EXPECT_EQ(graph.error().message, "file is larger than the 16 MiB limit") << size;
  }
}

TEST(LoadGraph, NamesAMissingFileAndAFolder) {
  const testing::TempFolder folder("shadetree-load-graph");
  Result<Graph> missing = load_graph((folder.path() / "absent.json").string());
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, "no such file");
  Result<Graph> directory = load_graph(folder.path().string());
  ASSERT_FALSE(directory);
  EXPECT_EQ(directory.error().message, "is a directory, not a graph file");
}

}  // namespace
}  // namespace shadetree
