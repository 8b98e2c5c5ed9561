#include "schedule/image_tiles.h"

#include <algorithm>
#include <atomic>

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include "schedule/thread_arena.h"

namespace shadetree {

Status for_each_tile(int width, int height, int tile_size, int threads, const std::function<long(const Tile&)>& render,
                     const ProgressCallback& progress, const std::atomic<bool>* cancel, TileClaims* claims) {
  const int tiles_x = (width + tile_size - 1) / tile_size;
  const int tiles_y = (height + tile_size - 1) / tile_size;
  const int tile_count = tiles_x * tiles_y;
  std::atomic<long> tiles_done{0}, items_done{0};
  const auto render_tile = [&](int tx, int ty) {
    const int x0 = tx * tile_size, y0 = ty * tile_size;
    const Tile tile{x0, y0, std::min(tile_size, width - x0), std::min(tile_size, height - y0)};
    const long items = render(tile);
    const long all_items = items_done += items;
    const long done = ++tiles_done;
    if (claims) claims->rendered(static_cast<long>(ty) * tiles_x + tx, tile);
    if (progress) progress(ProgressCount{done, tile_count, all_items});
  };
  tbb::task_arena arena(arena_concurrency(threads));
  arena.execute([&] {
    if (claims) {
      // Each of the arena's threads claims tiles until none is left.
      tbb::parallel_for(0, arena.max_concurrency(), [&](int) {
        for (long index; !(cancel && cancel->load(std::memory_order_relaxed)) && (index = claims->claim(tile_count)) >= 0;)
          render_tile(static_cast<int>(index % tiles_x), static_cast<int>(index / tiles_x));
      }, tbb::static_partitioner());
      return;
    }
    tbb::parallel_for(tbb::blocked_range2d<int>(0, tiles_y, 1, 0, tiles_x, 1), [&](const tbb::blocked_range2d<int>& range) {
      for (int ty = range.rows().begin(); ty < range.rows().end(); ++ty)
        for (int tx = range.cols().begin(); tx < range.cols().end(); ++tx) {
          if (cancel && cancel->load(std::memory_order_relaxed)) return;
          render_tile(tx, ty);
        }
    });
  });
  if (cancel && cancel->load()) return Diagnostic{ExitStatus::failure, {}, {}, {}, "render cancelled"};
  return success();
}

}  // namespace shadetree
