// The drivers' parallel loop: an image cut into square tiles, rendered on
// oneTBB's threads. Each tile is independent, so images are the same for
// any thread count.
#pragma once

#include <atomic>
#include <functional>

#include "graph/diagnostic.h"
#include "schedule/progress.h"

namespace shadetree {

struct Tile {
  int x0 = 0, y0 = 0;         // top-left pixel
  int width = 0, height = 0;  // at most the tile size (less on the right and bottom edges)
};

// render(tile) for every tile of `tile_size` pixels square of a `width` x
// `height` image, on `threads` threads (0: all cores); render returns the
// work the tile held (rays, samples), which progress, if set, is told of
// after each tile with the tiles done. Once `cancel` (if set) is true,
// tiles not yet started are skipped and the loop fails with "render
// cancelled": how the editor's server drops a preview a newer one has
// superseded.
Status for_each_tile(int width, int height, int tile_size, int threads, const std::function<long(const Tile&)>& render,
                     const ProgressCallback& progress, const std::atomic<bool>* cancel = nullptr);

}  // namespace shadetree
