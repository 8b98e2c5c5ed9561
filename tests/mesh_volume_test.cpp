// Meshes as volumes (Gilet & Dischler 2010 section 5): a mesh file becomes
// a signed distance grid through OpenVDB, and mesh_distance and
// mesh_closest read it in kernels.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "interp/interpreter.h"
#include "pipeline/compile_graph.h"
#include "io/graph_files.h"
#include "io/vdb_file.h"
#include "support/cube_mesh.h"
#include "support/graph_text.h"
#include "support/test_files.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;


class MeshVolume : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(folder_ / "cube.obj") << testing::cube_obj(0.5f); }
  testing::TempFolder temp_{"shadetree-mesh-volume"};
  const fs::path& folder_ = temp_.path();
};

float grid_value_at(const DistanceGrid& grid, const std::array<float, 3>& point) {
  int index[3];
  for (int axis = 0; axis < 3; ++axis)
    index[axis] = static_cast<int>(std::floor((point[axis] - grid.origin[axis]) / grid.voxel_size));
  return grid.distance[(static_cast<std::size_t>(index[2]) * grid.size[1] + index[1]) * grid.size[0] + index[0]];
}

// Negative inside, positive outside, and about the distance to the faces.
TEST_F(MeshVolume, CubeBecomesASignedDistanceGrid) {
  Result<TriangleMesh> mesh = load_mesh((folder_ / "cube.obj").string());
  ASSERT_TRUE(mesh.ok()) << mesh.error().to_string();
  Result<DistanceGrid> grid = mesh_distance_grid(*mesh, 48);
  ASSERT_TRUE(grid.ok()) << grid.error().to_string();
  EXPECT_EQ(grid->size, (std::array<int, 3>{48, 48, 48}));
  EXPECT_NEAR(grid->voxel_size, 1.2f / 48, 1e-6f);  // the cube's side padded by a tenth on each side
  const float voxel = grid->voxel_size;
  EXPECT_NEAR(grid_value_at(*grid, {0.0f, 0.0f, 0.0f}), -0.5f, voxel);
  EXPECT_NEAR(grid_value_at(*grid, {0.3f, 0.0f, 0.1f}), -0.2f, voxel);
  EXPECT_NEAR(grid_value_at(*grid, {0.58f, 0.0f, 0.0f}), 0.08f, voxel);
  EXPECT_GT(grid_value_at(*grid, {0.55f, 0.55f, 0.55f}), 0.0f);
}

// A volume graph's density, and its colour where it has one, at one point.
std::vector<float> evaluate(const std::string& nodes, const std::string& outputs, const std::array<float, 3>& point,
                            const GraphFiles& files) {
  Result<LoadedGraph> loaded =
      compile_graph_text(testing::graph_text(nodes, outputs, "", "volume"), "mesh.json", {}, {}, files);
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  if (!loaded) return {};
  float p[3] = {point[0], point[1], point[2]};
  SampleInputs inputs;
  for (int c = 0; c < 3; ++c) inputs.planes[global_def(GlobalId::P).first + c] = &p[c];
  const OutputLayout layout = output_layout(loaded->ir);
  std::vector<float> values(static_cast<std::size_t>(layout.plane_count));
  std::vector<float*> planes;
  for (float& value : values) planes.push_back(&value);
  make_interpreted_kernel(loaded->ir)->bind(loaded->params.data(), UniformInputs{})->run(inputs, planes.data(), 1);
  std::vector<float> result = {values[static_cast<std::size_t>(layout.plane(OutputId::density))]};
  if (layout.provides(OutputId::color))
    for (int c = 0; c < 3; ++c) result.push_back(values[static_cast<std::size_t>(layout.plane(OutputId::color, c))]);
  return result;
}

const char* const mesh_ops = R"({"id": "p", "op": "P"},
    {"id": "d", "op": "mesh_distance", "in": {"p": "p"}, "file": "ball.obj", "resolution": 48},
    {"id": "q", "op": "mesh_closest", "in": {"p": "p"}, "file": "ball.obj", "resolution": 48})";

// On the made-up sphere of radius 0.8 (tests/support/test_files.h), inside
// and outside the grid.
TEST_F(MeshVolume, DistanceAndClosestPointFollowTheSurface) {
  for (const std::array<float, 3> point : {std::array<float, 3>{0.3f, 0.2f, -0.1f}, {0.9f, 0.1f, 0.0f},
                                           {-0.2f, -1.0f, 0.4f}, {2.0f, 0.0f, 0.0f}}) {
    const std::vector<float> out = evaluate(mesh_ops, R"("density": "d", "color": "q")", point, testing::test_files());
    const float radius = std::sqrt(point[0] * point[0] + point[1] * point[1] + point[2] * point[2]);
    EXPECT_NEAR(out[0], radius - testing::test_mesh_radius, 0.02f) << point[0];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(out[1 + c], point[c] * testing::test_mesh_radius / radius, 0.03f) << point[0] << " axis " << c;
  }
}

// The mesh ops on a real file, through Assimp and OpenVDB.
TEST_F(MeshVolume, MeshFilesAreReadBesideTheGraph) {
  GraphFiles files = graph_files();
  const std::string graph = (folder_ / "g.json").string();
  GraphFiles beside;
  beside.distance_grid = [&](const std::string&, const std::string& path, int resolution) {
    return files.distance_grid(graph, path, resolution);
  };
  const std::string nodes = R"({"id": "p", "op": "P"},
      {"id": "d", "op": "mesh_distance", "in": {"p": "p"}, "file": "cube.obj"})";
  EXPECT_NEAR(evaluate(nodes, R"("density": "d")", {0.0f, 0.1f, 0.0f}, beside)[0], -0.4f, 0.03f);  // 0.4 below y = 0.5
  EXPECT_NEAR(evaluate(nodes, R"("density": "d")", {0.8f, 0.0f, 0.0f}, beside)[0], 0.3f, 0.03f);
  for (const char* bad : {"missing.obj", "../outside.obj"}) {
    Result<DistanceGrid> grid = files.distance_grid(graph, bad, 64);
    ASSERT_FALSE(grid.ok()) << bad;
    EXPECT_EQ(grid.error().status, ExitStatus::invalid_input) << bad;
  }
}

TEST_F(MeshVolume, BadAttributesAreOneLineErrorsOnTheNode) {
  auto error_of = [](const std::string& fields, const GraphFiles& files) {
    Result<LoadedGraph> loaded = compile_graph_text(
        testing::graph_text(R"({"id": "p", "op": "P"}, {"id": "m", "op": "mesh_distance", "in": {"p": "p"})" + fields + "}",
                            R"("density": "m")", "", "volume"),
        "g.json", {}, {}, files);
    return loaded ? std::string() : loaded.error().to_string();
  };
  EXPECT_EQ(error_of(R"(, "file": "a.obj", "resolution": 4)", testing::test_files()),
            R"(error: g.json: node "m": attribute "resolution" must be from 8 to 128)");
  EXPECT_EQ(error_of(R"(, "file": 7)", testing::test_files()),
            R"(error: g.json: node "m": attribute "file" must be the path of a mesh file (.obj, .ply))");
  EXPECT_EQ(error_of(R"(, "file": "a.obj")", GraphFiles{}),
            R"(error: g.json: node "m": mesh files cannot be read here (attribute "file"))");
}

}  // namespace
}  // namespace shadetree
