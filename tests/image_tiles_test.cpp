// The drivers' tile loop: every pixel in exactly one tile, and progress
// that counts tiles and the work their renders report.
#include <gtest/gtest.h>

#include <mutex>
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

}  // namespace
}  // namespace shadetree
