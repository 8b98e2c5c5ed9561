// The drivers' tile loop: every pixel in exactly one tile, progress that
// counts tiles and the work their renders report, and tiles shared with
// other processes through claims.
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <utility>
#include <vector>

#include "schedule/image_tiles.h"

namespace shadetree {
namespace {

TEST(ImageTiles, EveryPixelIsInOneTileAndProgressCountsTilesAndWork) {
  const int width = 70, height = 33, tile_size = 32;  // 3 x 2 tiles, the last ones cut short
  std::vector<int> covered(static_cast<std::size_t>(width) * height, 0);
  std::mutex mutex;
  std::vector<ProgressCount> reports;
  for_each_tile(
      width, height, tile_size, 2,
      [&](const Tile& tile) -> long {
        for (int y = tile.y0; y < tile.y0 + tile.height; ++y)
          for (int x = tile.x0; x < tile.x0 + tile.width; ++x) ++covered[static_cast<std::size_t>(y) * width + x];
        return static_cast<long>(tile.width) * tile.height;
      },
      [&](const ProgressCount& count) {
        std::lock_guard lock(mutex);
        reports.push_back(count);
      });
  for (int count : covered) EXPECT_EQ(count, 1);
  ASSERT_EQ(reports.size(), 6u);
  long largest_done = 0, largest_items = 0;
  for (const ProgressCount& count : reports) {
    EXPECT_EQ(count.total, 6);
    largest_done = std::max(largest_done, count.done);
    largest_items = std::max(largest_items, count.items);
  }
  EXPECT_EQ(largest_done, 6);
  EXPECT_EQ(largest_items, static_cast<long>(width) * height) << "the work of all tiles, once each";
}

// Claims as one process of several would see them: every other tile.
class EveryOtherTile : public TileClaims {
 public:
  long claim(long count) override {
    std::lock_guard lock(mutex);
    counts.push_back(count);
    const long index = next;
    next += 2;
    return index < count ? index : -1;
  }
  void rendered(long index, const Tile& tile) override {
    std::lock_guard lock(mutex);
    tiles.emplace_back(index, tile);
  }
  std::mutex mutex;
  long next = 1;
  std::vector<long> counts;
  std::vector<std::pair<long, Tile>> tiles;
};

TEST(ImageTiles, WithClaimsOnlyTheClaimedTilesAreRenderedAndReported) {
  const int width = 70, height = 33, tile_size = 32;  // tiles 0 1 2 / 3 4 5
  EveryOtherTile claims;
  std::vector<int> covered(static_cast<std::size_t>(width) * height, 0);
  std::mutex mutex;
  for_each_tile(
      width, height, tile_size, 2,
      [&](const Tile& tile) -> long {
        std::lock_guard lock(mutex);
        for (int y = tile.y0; y < tile.y0 + tile.height; ++y)
          for (int x = tile.x0; x < tile.x0 + tile.width; ++x) ++covered[static_cast<std::size_t>(y) * width + x];
        return 1;
      },
      {}, nullptr, &claims);
  for (long count : claims.counts) EXPECT_EQ(count, 6);
  ASSERT_EQ(claims.tiles.size(), 3u);
  std::sort(claims.tiles.begin(), claims.tiles.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const int expected[3][5] = {{1, 32, 0, 32, 32}, {3, 0, 32, 32, 1}, {5, 64, 32, 6, 1}};
  for (int i = 0; i < 3; ++i) {
    const auto& [index, tile] = claims.tiles[static_cast<std::size_t>(i)];
    EXPECT_EQ(index, expected[i][0]);
    EXPECT_EQ(tile.x0, expected[i][1]);
    EXPECT_EQ(tile.y0, expected[i][2]);
    EXPECT_EQ(tile.width, expected[i][3]);
    EXPECT_EQ(tile.height, expected[i][4]);
  }
  // Pixels of tile 1 (x 32..63, y 0..31) are rendered once, of tile 0 never.
  EXPECT_EQ(covered[40], 1);
  EXPECT_EQ(covered[5], 0);
  EXPECT_EQ(covered[static_cast<std::size_t>(32) * width + 69], 1);
}

}  // namespace
}  // namespace shadetree
