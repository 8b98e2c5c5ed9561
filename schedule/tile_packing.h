// Tiles of an image as one buffer: how the ranks of an MPI job send the
// tiles they rendered of a frame to rank 0, which writes it.
#pragma once

#include <vector>

#include "graph/diagnostic.h"
#include "nodes/image.h"
#include "schedule/image_tiles.h"

namespace shadetree {

// The pixels of `tiles` of `image`: per tile its x0, y0, width and height
// (ints), then its pixels, row by row.
std::vector<char> pack_tiles(const Image& image, const std::vector<Tile>& tiles);

// Copies packed tiles into `image`, and returns how many there were; a
// tile outside the image or a buffer cut short is an error.
Result<long> unpack_tiles(const std::vector<char>& packed, Image& image);

}  // namespace shadetree
