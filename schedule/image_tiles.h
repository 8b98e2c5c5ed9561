// The drivers' parallel loop: an image cut into square tiles, rendered on
// oneTBB's threads. Each tile is independent, so images are the same for
// any thread count.
#pragma once

#include <atomic>
#include <functional>

#include "graph/diagnostic.h"
#include "schedule/progress.h"

namespace shadetree {

struct Image;

struct Tile {
  int x0 = 0, y0 = 0;         // top-left pixel
  int width = 0, height = 0;  // at most the tile size (less on the right and bottom edges)
};

// Told of each tile of a frame once its pixels in `frame` are final, on
// the thread that rendered it: how the editor's server streams a slow
// preview as it fills in (server/preview_stream.h).
using TileSink = std::function<void(const Image& frame, const Tile& tile)>;

// The tiles of one image shared with other processes (an MPI job,
// schedule/mpi_job.h): for_each_tile renders only the tiles claimed here.
class TileClaims {
 public:
  virtual ~TileClaims() = default;
  // The index of the next tile this process renders, of `count` numbered
  // row by row, or -1 once none is left. Called from several threads.
  virtual long claim(long count) = 0;
  // The tile of index `index` is rendered.
  virtual void rendered(long index, const Tile& tile) = 0;
};

// render(tile) for every tile of `tile_size` pixels square of a `width` x
// `height` image, on `threads` threads (0: all cores); render returns the
// work the tile held (rays, samples), which progress, if set, is told of
// after each tile with the tiles done. Once `cancel` (if set) is true,
// tiles not yet started are skipped and the loop fails with "render
// cancelled": how the editor's server drops a preview a newer one has
// superseded. With `claims`, only the tiles it hands out are rendered,
// each thread claiming its next when done with one.
Status for_each_tile(int width, int height, int tile_size, int threads, const std::function<long(const Tile&)>& render,
                     const ProgressCallback& progress, const std::atomic<bool>* cancel = nullptr,
                     TileClaims* claims = nullptr);

}  // namespace shadetree
