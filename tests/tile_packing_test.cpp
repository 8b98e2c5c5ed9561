// Tiles of an image packed into one buffer and back (schedule/tile_packing.h),
// as the ranks of an MPI job send theirs to rank 0; and, through every
// driver, two processes' shares of a frame's tiles gathered into the
// frame a single process renders.
#include <gtest/gtest.h>

#include <mutex>
#include <string>

#include "interp/interpreter.h"
#include "pipeline/compile_graph.h"
#include "render/graph_kinds.h"
#include "schedule/tile_packing.h"
#include "support/gallery.h"

namespace shadetree {
namespace {

Image numbered(int width, int height, int channels) {
  Image image{width, height, channels, {}};
  for (int i = 0; i < width * height * channels; ++i) image.pixels.push_back(static_cast<float>(i));
  return image;
}

TEST(TilePacking, PackedTilesLandWhereTheyCameFrom) {
  const Image source = numbered(10, 7, 3);
  const std::vector<Tile> tiles = {{0, 0, 4, 4}, {8, 4, 2, 3}, {4, 0, 6, 4}};
  const std::vector<char> packed = pack_tiles(source, tiles);
  EXPECT_EQ(packed.size(), 3 * 16 + sizeof(float) * 3 * (16 + 6 + 24));
  Image target{10, 7, 3, std::vector<float>(10 * 7 * 3, -1.0f)};
  Result<long> unpacked = unpack_tiles(packed, target);
  ASSERT_TRUE(unpacked.ok()) << unpacked.error().to_string();
  EXPECT_EQ(*unpacked, 3);
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 10; ++x) {
      const bool inside = y < 4 || x >= 8;
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = (static_cast<std::size_t>(y) * 10 + x) * 3 + c;
        EXPECT_EQ(target.pixels[i], inside ? source.pixels[i] : -1.0f) << x << "," << y;
      }
    }
  EXPECT_EQ(*unpack_tiles({}, target), 0);
}

TEST(TilePacking, TilesOutsideTheImageAndShortBuffersAreRefused) {
  Image small = numbered(4, 4, 1);
  const std::vector<char> packed = pack_tiles(numbered(8, 8, 1), {{4, 4, 4, 4}});
  EXPECT_EQ(unpack_tiles(packed, small).error().message, "a packed tile lies outside the image");
  std::vector<char> cut = pack_tiles(small, {{0, 0, 4, 4}});
  cut.pop_back();
  EXPECT_EQ(unpack_tiles(cut, small).error().message, "a packed tile is cut short");
  cut.resize(10);
  EXPECT_EQ(unpack_tiles(cut, small).error().message, "a packed tile is cut short");
}

// One of two processes sharing a frame: tiles alternate between them, as
// a dynamic queue might hand them out.
class HalfOfTheTiles : public TileClaims {
 public:
  explicit HalfOfTheTiles(long first) : next_(first) {}
  long claim(long count) override {
    std::lock_guard lock(mutex_);
    const long index = next_;
    next_ += 2;
    return index < count ? index : -1;
  }
  void rendered(long, const Tile& tile) override {
    std::lock_guard lock(mutex_);
    tiles.push_back(tile);
  }
  std::vector<Tile> tiles;

 private:
  std::mutex mutex_;
  long next_;
};

class SharedFrames : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedFrames, TwoSharesGatheredAreTheWholeFrame) {
  Result<LoadedGraph> loaded = testing::load_gallery_graph(SHADETREE_SOURCE_DIR "/graphs/" + std::string(GetParam()));
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  std::unique_ptr<Kernel> kernel = make_interpreted_kernel(loaded->ir);
  RenderRequest request;
  request.size = std::make_pair(100, 70);
  Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded->graph, request);
  ASSERT_TRUE(renderer.ok()) << renderer.error().to_string();
  Result<Image> whole = (*renderer)->render(*kernel, loaded->params, 3.0f, {}, nullptr);
  ASSERT_TRUE(whole.ok());
  HalfOfTheTiles first(0), second(1);
  Result<Image> mine = (*renderer)->render(*kernel, loaded->params, 3.0f, {}, nullptr, &first);
  Result<Image> theirs = (*renderer)->render(*kernel, loaded->params, 3.0f, {}, nullptr, &second);
  ASSERT_TRUE(mine.ok() && theirs.ok());
  ASSERT_FALSE(first.tiles.empty());
  ASSERT_FALSE(second.tiles.empty());
  ASSERT_TRUE(unpack_tiles(pack_tiles(*theirs, second.tiles), *mine).ok());
  ASSERT_EQ(mine->pixels.size(), whole->pixels.size());
  for (std::size_t i = 0; i < whole->pixels.size(); ++i)
    ASSERT_EQ(mine->pixels[i], whole->pixels[i]) << "value " << i;
}

// A texture, a surface on its scene, volumes with cached shadows over a
// floor and with empty space, and an environment.
INSTANTIATE_TEST_SUITE_P(EveryKind, SharedFrames,
                         ::testing::Values("marble.json", "donut_bumpy.json", "cloud_over_floor.json", "tribble.json",
                                           "sunset_sky.json"));

}  // namespace
}  // namespace shadetree
