// Images made up from their names, for tests of the `image` op that need
// no files: "4x2x3.png" is 4 x 2 pixels of 3 channels, channel c of the
// pixel in column i and row j (from the top) being (i + 10 j + 100 c) / 1000.
#pragma once

#include <cstdio>
#include <string>

#include "graph/check.h"

namespace shadetree::testing {

inline float test_image_value(int column, int row, int channel) {
  return static_cast<float>(column + 10 * row + 100 * channel) / 1000.0f;
}

inline ImageReader test_image_reader() {
  return [](const std::string&, const std::string& path) -> Result<Image> {
    Image image;
    if (std::sscanf(path.c_str(), "%dx%dx%d", &image.width, &image.height, &image.channels) != 3)
      return invalid_input("no test image \"" + path + "\"");
    for (int row = 0; row < image.height; ++row)
      for (int column = 0; column < image.width; ++column)
        for (int c = 0; c < image.channels; ++c) image.pixels.push_back(test_image_value(column, row, c));
    return image;
  };
}

}  // namespace shadetree::testing
