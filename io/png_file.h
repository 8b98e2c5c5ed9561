// PNG files through libpng, without OpenImageIO: writing a PNG is what
// most renders end with, and loading OpenImageIO for it cost every such
// process a quarter of a second of dynamic linking (issue 23).
#pragma once

#include <string>

#include "nodes/image.h"

namespace shadetree {

// Writes `image` to `file` as an 8- or 16-bit PNG (grey, grey and alpha,
// RGB or RGBA by its channel count), each value clamped to [0,1] and
// rounded to the nearest step (NaN is 0). Returns why it could not, or "".
std::string write_png(const Image& image, const std::string& file, int bits);

}  // namespace shadetree
