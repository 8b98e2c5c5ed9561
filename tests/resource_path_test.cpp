// Files named by a graph stay inside its folder unless the user allows
// another with --search-path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

#include "io/resource_path.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

class ResourcePath : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("shadetree-resource-" + std::to_string(::getpid()));
    fs::create_directories(root_ / "graphs" / "meshes");
    fs::create_directories(root_ / "elsewhere");
    std::ofstream(root_ / "graphs" / "meshes" / "a.obj") << "v 0 0 0\n";
    std::ofstream(root_ / "elsewhere" / "b.obj") << "v 0 0 0\n";
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string graph() const { return (root_ / "graphs" / "g.json").string(); }
  fs::path root_;
};

TEST_F(ResourcePath, ResolvesRelativeToTheGraphFolder) {
  Result<std::string> path = resolve_graph_resource(graph(), "meshes/a.obj", {}, "file");
  ASSERT_TRUE(path.ok()) << path.error().to_string();
  EXPECT_EQ(fs::path(*path), fs::canonical(root_ / "graphs" / "meshes" / "a.obj"));
}

TEST_F(ResourcePath, RefusesPathsThatLeaveTheGraphFolder) {
  for (const std::string& escape : {std::string("../elsewhere/b.obj"), (root_ / "elsewhere" / "b.obj").string(),
                                    std::string("/etc/passwd"), std::string("meshes/../../elsewhere/b.obj")}) {
    Result<std::string> path = resolve_graph_resource(graph(), escape, {}, "scene object #1 file");
    ASSERT_FALSE(path.ok()) << escape;
    EXPECT_NE(path.error().message.find("outside the graph's folder"), std::string::npos);
    EXPECT_EQ(path.error().status, ExitStatus::invalid_input);
  }
}

// Regression: a graph file named without a folder had an empty folder,
// under which every path was taken to lie.
TEST_F(ResourcePath, GraphInTheCurrentFolderStillConfinesPaths) {
  const fs::path previous = fs::current_path();
  fs::current_path(root_ / "graphs");
  Result<std::string> inside = resolve_graph_resource("g.json", "meshes/a.obj", {}, "file");
  Result<std::string> outside = resolve_graph_resource("g.json", "../elsewhere/b.obj", {}, "file");
  fs::current_path(previous);
  EXPECT_TRUE(inside.ok());
  ASSERT_FALSE(outside.ok());
  EXPECT_NE(outside.error().message.find("outside the graph's folder"), std::string::npos);
}

TEST_F(ResourcePath, SearchPathsAllowOtherFolders) {
  Result<std::string> path =
      resolve_graph_resource(graph(), "../elsewhere/b.obj", {(root_ / "elsewhere").string()}, "file");
  EXPECT_TRUE(path.ok());
  // A sibling whose name starts like an allowed folder is not inside it.
  fs::create_directories(root_ / "elsewhere2");
  std::ofstream(root_ / "elsewhere2" / "c.obj") << "v 0 0 0\n";
  EXPECT_FALSE(resolve_graph_resource(graph(), "../elsewhere2/c.obj", {(root_ / "elsewhere").string()}, "file").ok());
}

TEST_F(ResourcePath, SymbolicLinksAreFollowedBeforeTheCheck) {
  fs::create_symlink(root_ / "elsewhere" / "b.obj", root_ / "graphs" / "link.obj");
  EXPECT_FALSE(resolve_graph_resource(graph(), "link.obj", {}, "file").ok());
}

// Found in this session's hostile pass: a scene environment naming a pipe
// in the graph's folder made check wait forever on it. Only regular files
// (or missing ones, which their readers name) resolve.
TEST_F(ResourcePath, PipesAndFoldersAreNotFiles) {
  ASSERT_EQ(::mkfifo((root_ / "graphs" / "pipe.json").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", root_ / "graphs" / "zero.obj");
  for (const char* name : {"pipe.json", "meshes", "zero.obj"}) {
    Result<std::string> path = resolve_graph_resource(graph(), name, {"/dev"}, "scene environment");
    ASSERT_FALSE(path.ok()) << name;
    EXPECT_EQ(path.error().to_string(), "error: " + graph() + ": scene environment \"" + name +
                                            "\" is not a regular file");
  }
  EXPECT_TRUE(resolve_graph_resource(graph(), "not_there_yet.json", {}, "scene environment").ok());
}

}  // namespace
}  // namespace shadetree
