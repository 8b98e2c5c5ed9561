#include "schedule/tile_packing.h"

#include <cstring>

namespace shadetree {

std::vector<char> pack_tiles(const Image& image, const std::vector<Tile>& tiles) {
  std::size_t bytes = 0;
  for (const Tile& tile : tiles)
    bytes += 4 * sizeof(int) + sizeof(float) * static_cast<std::size_t>(tile.width) * tile.height * image.channels;
  std::vector<char> packed(bytes);
  char* at = packed.data();
  for (const Tile& tile : tiles) {
    const int corner[4] = {tile.x0, tile.y0, tile.width, tile.height};
    std::memcpy(at, corner, sizeof corner);
    at += sizeof corner;
    const std::size_t row = sizeof(float) * static_cast<std::size_t>(tile.width) * image.channels;
    for (int y = tile.y0; y < tile.y0 + tile.height; ++y, at += row)
      std::memcpy(at, image.pixels.data() + (static_cast<std::size_t>(y) * image.width + tile.x0) * image.channels, row);
  }
  return packed;
}

Result<long> unpack_tiles(const std::vector<char>& packed, Image& image) {
  long tiles = 0;
  for (std::size_t at = 0; at < packed.size(); ++tiles) {
    int corner[4];
    if (packed.size() - at < sizeof corner) return failure("a packed tile is cut short");
    std::memcpy(corner, packed.data() + at, sizeof corner);
    at += sizeof corner;
    const auto [x0, y0, width, height] = corner;
    if (x0 < 0 || y0 < 0 || width < 1 || height < 1 || width > image.width - x0 || height > image.height - y0)
      return failure("a packed tile lies outside the image");
    const std::size_t row = sizeof(float) * static_cast<std::size_t>(width) * image.channels;
    if ((packed.size() - at) / row < static_cast<std::size_t>(height)) return failure("a packed tile is cut short");
    for (int y = y0; y < y0 + height; ++y, at += row)
      std::memcpy(image.pixels.data() + (static_cast<std::size_t>(y) * image.width + x0) * image.channels,
                  packed.data() + at, row);
  }
  return tiles;
}

}  // namespace shadetree
