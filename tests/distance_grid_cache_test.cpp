// Meshes' distance grids in the user's cache folder: a grid comes back as
// it was stored, and only for the same mesh file with the same bytes, at
// the same resolution; a damaged file is a miss, never a wrong grid.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/distance_grid_cache.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

struct CacheFolder {
  fs::path folder = fs::temp_directory_path() / ("shadetree-distance-grid-cache-" + std::to_string(::getpid()));
  fs::path mesh = folder / "mesh.obj";
  CacheFolder() {
    fs::create_directories(folder);
    std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  }
  ~CacheFolder() { fs::remove_all(folder); }
  fs::path only_grid_file() const {
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".bin") return entry.path();
    return {};
  }
};

DistanceGrid some_grid() {
  DistanceGrid grid;
  grid.size = {3, 2, 4};
  grid.origin = {-1.5f, 0.25f, 2.0f};
  grid.voxel_size = 0.125f;
  for (int v = 0; v < 3 * 2 * 4; ++v) grid.distance.push_back(0.1f * static_cast<float>(v) - 1.0f);
  return grid;
}

TEST(DistanceGridCache, AGridComesBackAsItWasStored) {
  const CacheFolder cache;
  const DistanceGridSource source{cache.mesh, 64};
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, source));
  store_distance_grid(cache.folder, source, some_grid());
  const std::optional<DistanceGrid> read = read_cached_distance_grid(cache.folder, source);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->size, some_grid().size);
  EXPECT_EQ(read->origin, some_grid().origin);
  EXPECT_EQ(read->voxel_size, some_grid().voxel_size);
  EXPECT_EQ(read->distance, some_grid().distance);
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, {cache.mesh, 32})) << "another resolution";
  EXPECT_FALSE(read_cached_distance_grid({}, source)) << "no cache folder";
}

TEST(DistanceGridCache, AChangedMeshFileIsAMiss) {
  const CacheFolder cache;
  const DistanceGridSource source{cache.mesh, 64};
  store_distance_grid(cache.folder, source, some_grid());
  // The same size, other bytes, at once (a modification time may not change).
  std::string text;
  {
    std::ifstream in(cache.mesh);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  text[2] = '1';
  std::ofstream(cache.mesh, std::ios::trunc) << text;
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, source)) << "rewritten";
  store_distance_grid(cache.folder, source, some_grid());
  std::ofstream(cache.mesh, std::ios::app) << "v 2 2 2\n";
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, source)) << "grown";
  fs::remove(cache.mesh);
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, source)) << "gone";
}

TEST(DistanceGridCache, ADamagedFileIsAMiss) {
  const CacheFolder cache;
  const DistanceGridSource source{cache.mesh, 64};
  store_distance_grid(cache.folder, source, some_grid());
  const fs::path file = cache.only_grid_file();
  ASSERT_FALSE(file.empty());
  fs::resize_file(file, fs::file_size(file) - 4);
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, source)) << "cut short";
  store_distance_grid(cache.folder, source, some_grid());
  std::ofstream(file, std::ios::app | std::ios::binary) << "more";
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, source)) << "grown";
  // Sides past any resolution (here 2^30 voxels a side) are refused before
  // anything is allocated for them.
  store_distance_grid(cache.folder, source, some_grid());
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::size_t sides = bytes.find('\n') + 1;
  const int huge = 1 << 30;
  bytes.replace(sides, sizeof huge, reinterpret_cast<const char*>(&huge), sizeof huge);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_FALSE(read_cached_distance_grid(cache.folder, source)) << "absurd size";
}

}  // namespace
}  // namespace shadetree
