// An image as the drivers make it and image_output writes it.
#pragma once

#include <vector>

namespace shadetree {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;           // 3 (rgb) or 4 (rgba)
  std::vector<float> pixels;  // row-major, top row first, interleaved
};

}  // namespace shadetree
