// Voxelizing a volume graph: the grid's layout over the bounds, and the
// densities at voxel centres against the graph's closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "interp/interpreter.h"
#include "nodes/semantics/soft_objects.h"
#include "pipeline/compile_graph.h"
#include "render/voxelize.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

LoadedGraph soft_sphere_graph() {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "p", "op": "P"}, {"id": "s", "op": "sphere", "in": {"p": "p", "radius": 0.8, "softness": 0.4}},
                             {"id": "c", "op": "to_color", "in": {"v": "p"}})",
                          R"("density": "s", "color": "c")", "", "volume"),
      "sphere.json");
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  return std::move(*loaded);
}

VolumeDesc bounds(std::array<float, 3> lo, std::array<float, 3> hi) {
  VolumeDesc volume;
  volume.bounds_min = lo;
  volume.bounds_max = hi;
  return volume;
}

TEST(Voxelize, CubicVoxelsCoverTheBoundsAlongTheLongestSide) {
  const LoadedGraph loaded = soft_sphere_graph();
  VoxelizeOptions options;
  options.resolution = 20;
  Result<VoxelGrid> grid =
      voxelize(*make_interpreted_kernel(loaded.ir), loaded.params, bounds({-1, -0.5f, 0}, {1, 0.5f, 0.3f}), options);
  ASSERT_TRUE(grid.ok()) << grid.error().to_string();
  EXPECT_FLOAT_EQ(grid->voxel_size, 0.1f);
  EXPECT_EQ(grid->size, (std::array<int, 3>{20, 10, 3}));
  EXPECT_EQ(grid->origin, (std::array<float, 3>{-1, -0.5f, 0}));
  EXPECT_EQ(grid->density.size(), 20u * 10 * 3);
  EXPECT_EQ(grid->color.size(), 3 * grid->density.size());
}

TEST(Voxelize, DensitiesAndColoursAreTheGraphsAtVoxelCentres) {
  const LoadedGraph loaded = soft_sphere_graph();
  VoxelizeOptions options;
  options.resolution = 16;
  options.threads = 2;
  Result<VoxelGrid> grid =
      voxelize(*make_interpreted_kernel(loaded.ir), loaded.params, bounds({-1, -1, -1}, {1, 1, 1}), options);
  ASSERT_TRUE(grid.ok());
  for (int k = 0; k < 16; k += 3)
    for (int j = 0; j < 16; j += 5)
      for (int i = 0; i < 16; ++i) {
        const float x = -1 + (i + 0.5f) * 0.125f, y = -1 + (j + 0.5f) * 0.125f, z = -1 + (k + 0.5f) * 0.125f;
        const float expected = semantics::soft_sphere<float>({x, y, z}, {0, 0, 0}, 0.8f, 0.4f);
        EXPECT_FLOAT_EQ(grid->density[grid->index(i, j, k)], expected) << i << " " << j << " " << k;
        EXPECT_FLOAT_EQ(grid->color[3 * grid->index(i, j, k) + 1], y);
      }
}

TEST(Voxelize, RefusesOtherKindsAndResolutions) {
  const LoadedGraph loaded = soft_sphere_graph();
  for (int resolution : {0, max_voxel_resolution + 1}) {
    VoxelizeOptions options;
    options.resolution = resolution;
    Result<VoxelGrid> grid =
        voxelize(*make_interpreted_kernel(loaded.ir), loaded.params, bounds({-1, -1, -1}, {1, 1, 1}), options);
    ASSERT_FALSE(grid.ok());
    EXPECT_EQ(grid.error().status, ExitStatus::invalid_input);
  }
  Result<LoadedGraph> texture = compile_graph_text(testing::graph_text("", R"("color": 1)"), "t.json");
  ASSERT_TRUE(texture.ok());
  EXPECT_FALSE(voxelize(*make_interpreted_kernel(texture->ir), texture->params, bounds({-1, -1, -1}, {1, 1, 1}), {}).ok());
}

}  // namespace
}  // namespace shadetree
