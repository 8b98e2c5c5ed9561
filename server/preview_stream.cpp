#include "server/preview_stream.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace shadetree {
namespace {

void append_u32(std::string& bytes, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<char>((value >> shift) & 0xff));
}

std::string record_head(std::uint32_t x, std::uint32_t y, std::uint32_t width, std::uint32_t height) {
  std::string head;
  for (std::uint32_t value : {x, y, width, height}) append_u32(head, value);
  return head;
}

}  // namespace

std::string rgba_bytes(const Image& image, const Tile& region) {
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(region.width) * region.height * 4);
  for (int y = region.y0; y < region.y0 + region.height; ++y)
    for (int x = region.x0; x < region.x0 + region.width; ++x) {
      const float* pixel = image.pixels.data() + (static_cast<std::size_t>(y) * image.width + x) * image.channels;
      for (int c = 0; c < 4; ++c) {
        const float value = c < image.channels ? pixel[c] : 1.0f;
        const float clamped = std::isnan(value) ? 0.0f : std::clamp(value, 0.0f, 1.0f);
        bytes.push_back(static_cast<char>(static_cast<unsigned char>(clamped * 255.0f + 0.5f)));
      }
    }
  return bytes;
}

std::string rgba_bytes(const Image& image) { return rgba_bytes(image, {0, 0, image.width, image.height}); }

std::string tile_record(const Image& frame, const Tile& tile) {
  return record_head(static_cast<std::uint32_t>(tile.x0), static_cast<std::uint32_t>(tile.y0),
                     static_cast<std::uint32_t>(tile.width), static_cast<std::uint32_t>(tile.height)) +
         rgba_bytes(frame, tile);
}

std::string end_record(std::string_view error) {
  return record_head(0, 0, 0, static_cast<std::uint32_t>(error.size())) + std::string(error);
}

}  // namespace shadetree
