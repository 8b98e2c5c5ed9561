// The path policy (graph/file_path.h) and every site that opens or writes
// a file on a path someone else chose: each refuses a NUL, a control
// character and an over-long name before it touches the disk.
#include "graph/file_path.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include <unistd.h>

#include "graph/parse.h"
#include "io/image_output.h"
#include "io/mesh_file.h"
#include "io/output_file.h"
#include "io/resource_path.h"
#include "io/vdb_file.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

TEST(CheckPathText, TakesOrdinaryPaths) {
  for (const char* path : {"g.json", "graphs/marble.json", "/tmp/out.exr", "caf\xc3\xa9/x.png", "a b/c.obj"})
    EXPECT_TRUE(check_path_text(path, "file").ok()) << path;
}

TEST(CheckPathText, RefusesNulControlCharactersAndOverLongNames) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {std::string("images/ocean.png\0.json", 22), "NUL"},
      {"run\n.json", "control character"},
      {"a\x1b[2J.json", "control character"},
      {"", "empty"},
      {std::string(256, 'n') + ".json", "longer than 255 bytes"},
      {"dir/" + std::string(300, 'd') + "/g.json", "longer than 255 bytes"},
      {std::string(5000, 'a'), "longer than 4096 bytes"},
  };
  for (const auto& [path, words] : cases) {
    Status status = check_path_text(path, "output");
    ASSERT_FALSE(status.ok()) << words;
    EXPECT_EQ(status.error().status, ExitStatus::invalid_input);
    const std::string line = status.error().to_string();
    EXPECT_NE(line.find(words), std::string::npos) << line;
    EXPECT_LT(line.size(), 400u) << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  }
}

// Each site given a path holding a NUL: one that checked only the text
// after the NUL would open or write the file the NUL cuts it to. The
// editor server's routes go through ServedFolder::resolve, tested in
// EditorServerTest.ANulInAPathCannotSaveOverAnotherFile.
TEST(FilePathPolicy, EverySiteThatOpensOrWritesAFileRefusesANulInItsPath) {
  const fs::path folder = fs::temp_directory_path() / ("shadetree-file-path-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string real = (folder / "real").string();
  const std::string cut = real + std::string("\0.x", 3);
  const std::vector<std::pair<std::string, std::function<Diagnostic()>>> sites = {
      {"load_graph", [&] { return load_graph(cut).error(); }},
      {"resolve_graph_resource", [&] { return resolve_graph_resource((folder / "g.json").string(), "real" + std::string("\0.png", 5), {}, "image").error(); }},
      {"load_mesh", [&] { return load_mesh(cut).error(); }},
      {"read_image", [&] { return read_image(cut).error(); }},
      {"read_vdb", [&] { return read_vdb(cut).error(); }},
      {"write_image", [&] { return write_image(Image{1, 1, 1, {0.5f}}, cut + ".png").error(); }},
      {"write_vdb", [&] { return write_vdb(VoxelGrid{}, cut + ".vdb").error(); }},
      {"check_output_folder", [&] { return check_output_folder(cut).error(); }},
  };
  for (const auto& [site, refuse] : sites) {
    const Diagnostic error = refuse();
    EXPECT_EQ(error.status, ExitStatus::invalid_input) << site;
    EXPECT_NE(error.message.find("NUL"), std::string::npos) << site << ": " << error.to_string();
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace shadetree
