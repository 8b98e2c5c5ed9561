// A preview streamed as its tiles are done (POST /api/preview?stream=1):
// a slow volume fills in over its draft tile by tile instead of showing
// nothing new until the whole frame is marched. The body is a sequence of
// records, every integer a little-endian uint32:
//   a tile: x, y, width, height (width > 0), then width x height RGBA
//           bytes, rows from the top, as a whole preview's bytes are;
//   the end: 0, 0, 0, n, then n bytes of UTF-8, the render's error, or
//           none (n = 0) when it succeeded. Every stream ends with one;
//           a stream cut before it failed.
#pragma once

#include <string>
#include <string_view>

#include "nodes/image.h"
#include "schedule/image_tiles.h"

namespace shadetree {

// The region's float pixels as bytes, clamped to [0, 1] as PNG output
// does; RGBA, alpha 1 where the image has none.
std::string rgba_bytes(const Image& image, const Tile& region);
std::string rgba_bytes(const Image& image);  // the whole image

std::string tile_record(const Image& frame, const Tile& tile);
std::string end_record(std::string_view error);

}  // namespace shadetree
