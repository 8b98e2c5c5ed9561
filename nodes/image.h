// An image in memory: what the drivers render, what image files hold, and
// what the `image` op samples (its pixels become the op's attribute data).
#pragma once

#include <vector>

namespace shadetree {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;           // 1 (grey) to 4 (rgba)
  std::vector<float> pixels;  // row-major, top row first, interleaved
};

}  // namespace shadetree
