// VDB files: a voxelized soft sphere written through OpenVDB reads back
// with the densities and colours of its voxels and their place in space.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "interp/interpreter.h"
#include "pipeline/compile_graph.h"
#include "io/vdb_file.h"
#include "render/voxelize.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

class VdbFile : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("shadetree-vdb-" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(VdbFile, SoftSphereReadsBackVoxelForVoxel) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "p", "op": "P"}, {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 0.7, "softness": 0.5}},
                             {"id": "c", "op": "to_color", "in": {"v": "p"}})",
                          R"("density": "s", "color": "c")", "", "volume"),
      "sphere.json");
  ASSERT_TRUE(loaded.ok());
  VolumeDesc volume;
  volume.bounds_min = {-1.0f, -1.0f, -0.5f};
  volume.bounds_max = {1.0f, 1.0f, 0.5f};
  VoxelizeOptions options;
  options.resolution = 24;
  Result<VoxelGrid> grid = voxelize(*make_interpreted_kernel(loaded->ir), loaded->params, volume, options);
  ASSERT_TRUE(grid.ok());
  const std::string path = (folder_ / "sphere.vdb").string();
  Status written = write_vdb(*grid, path);
  ASSERT_TRUE(written.ok()) << written.error().to_string();
  Result<VoxelGrid> read = read_vdb(path);
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  EXPECT_EQ(read->size, grid->size);
  EXPECT_NEAR(read->voxel_size, grid->voxel_size, 1e-6f);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(read->origin[axis], grid->origin[axis], 1e-5f);
  EXPECT_EQ(read->density, grid->density);
  // Colour is kept where there is density (elsewhere the background, 0).
  for (std::size_t v = 0; v < grid->density.size(); ++v)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(read->color[3 * v + c], grid->density[v] > 0.0f ? grid->color[3 * v + c] : 0.0f);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator{}), 1);  // no temporary left
}

TEST_F(VdbFile, MissingAndBrokenFilesAreOneLineFailures) {
  std::ofstream(folder_ / "broken.vdb") << "not a vdb";
  for (const char* name : {"missing.vdb", "broken.vdb"}) {
    Result<VoxelGrid> read = read_vdb((folder_ / name).string());
    ASSERT_FALSE(read.ok()) << name;
    EXPECT_EQ(read.error().to_string().find('\n'), std::string::npos);
  }
  VoxelGrid grid{{1, 1, 1}, {0, 0, 0}, 1.0f, {0.5f}, {}};
  EXPECT_FALSE(write_vdb(grid, (folder_ / "no" / "such" / "folder.vdb").string()).ok());
}

}  // namespace
}  // namespace shadetree
