// Volumes' empty space in the user's cache folder: a grid comes back as
// it was stored, and only for the same program, outputs, params, uniform
// globals and bounds; a damaged file is a miss, never a wrong grid.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <glm/geometric.hpp>

#include "render/occupancy_grid_cache.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

// Empty outside the ball of radius 0.5 about the origin, by an exact box test.
BoxContents meets_ball(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 nearest = glm::clamp(glm::vec3(0.0f), lo, hi);
  return glm::length(nearest) > 0.5f ? BoxContents::empty : BoxContents::some;
}

OccupancyGrid ball_grid() {
  Result<std::optional<OccupancyGrid>> grid =
      OccupancyGrid::build(glm::vec3(-1.0f), glm::vec3(1.0f), meets_ball, 0.0, 2, nullptr);
  EXPECT_TRUE(grid.ok() && grid->has_value());
  for (bool surveyed : {true, false}) EXPECT_TRUE((*grid)->refine(meets_ball, surveyed, 2, nullptr).ok());
  return std::move(**grid);
}

// A program of one constant: the cache reads programs only as their text.
ShadeIR some_program(float constant) {
  ShadeIR ir;
  ir.kind = GraphKind::volume;
  IrInstr instr;
  instr.kind = IrOpKind::constant;
  instr.data_count = 1;
  ir.code.push_back(instr);
  ir.data.push_back(constant);
  ir.outputs.push_back({OutputId::density, Type::float_, 0});
  return ir;
}

struct Source {
  ShadeIR ir = some_program(0.5f);
  std::vector<OutputId> bounded{OutputId::density};
  std::vector<float> params{1.0f, 2.0f};
  UniformInputs uniforms;
  glm::vec3 lo{-1.0f}, hi{1.0f};

  EmptySpaceSource source() const { return empty_space_source(ir, bounded, params, uniforms, lo, hi); }
};

fs::path only_file(const fs::path& folder) {
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".bin") return entry.path();
  return {};
}

TEST(OccupancyGridCache, AStoredGridIsReadBackAsItWas) {
  testing::TempFolder folder("shadetree-empty-space");
  const OccupancyGrid grid = ball_grid();
  store_empty_space(folder.path(), Source().source(), grid);
  const std::optional<OccupancyGrid> read = read_cached_empty_space(folder.path(), Source().source());
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->serialized(), grid.serialized());
  EXPECT_GT(read->empty_fraction(), 0.8);
}

// Each thing bounding depends on, changed, misses.
TEST(OccupancyGridCache, AnythingBoundingDependsOnChangedIsAMiss) {
  testing::TempFolder folder("shadetree-empty-space");
  store_empty_space(folder.path(), Source().source(), ball_grid());
  std::vector<Source> changed(6);
  changed[0].ir = some_program(0.25f);
  changed[1].bounded = {OutputId::opacity};
  changed[2].params[1] = 3.0f;
  changed[3].uniforms.set(GlobalId::time, 1.0f / 24.0f);
  changed[4].lo.z = -1.5f;
  changed[5].hi.x = 1.0f + 1e-6f;
  for (std::size_t n = 0; n < changed.size(); ++n)
    EXPECT_FALSE(read_cached_empty_space(folder.path(), changed[n].source()).has_value()) << n;
  EXPECT_TRUE(read_cached_empty_space(folder.path(), Source().source()).has_value());
}

// A file cut short, grown or with a flipped bit in its grid is not read;
// nor is anything from, or kept in, no folder.
TEST(OccupancyGridCache, ADamagedFileIsAMiss) {
  testing::TempFolder folder("shadetree-empty-space");
  const OccupancyGrid grid = ball_grid();
  store_empty_space(folder.path(), Source().source(), grid);
  const fs::path file = only_file(folder.path());
  ASSERT_FALSE(file.empty());
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto write = [&](const std::string& text) { std::ofstream(file, std::ios::binary) << text; };
  write(bytes.substr(0, bytes.size() - 1));
  EXPECT_FALSE(read_cached_empty_space(folder.path(), Source().source()).has_value());
  write(bytes + "x");
  EXPECT_FALSE(read_cached_empty_space(folder.path(), Source().source()).has_value());
  std::string flipped = bytes;
  flipped[bytes.size() - 100] = static_cast<char>(flipped[bytes.size() - 100] ^ 4);
  write(flipped);
  EXPECT_FALSE(read_cached_empty_space(folder.path(), Source().source()).has_value());
  write(bytes);
  EXPECT_TRUE(read_cached_empty_space(folder.path(), Source().source()).has_value());
  store_empty_space({}, Source().source(), grid);
  EXPECT_FALSE(read_cached_empty_space({}, Source().source()).has_value());
}

}  // namespace
}  // namespace shadetree
