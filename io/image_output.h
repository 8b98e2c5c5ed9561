// Image files through OpenImageIO. Writes go to a temporary file in the
// target's folder that is renamed over the target only once complete, so a
// failed render never leaves a partial or corrupt image behind.
#pragma once

#include <string>

#include "graph/diagnostic.h"
#include "nodes/image.h"

namespace shadetree {

// Whether `path` names a format we write (.png or .exr) in an existing
// folder: checked before a render so that a typo costs no render time.
Status check_image_path(const std::string& path);

// PNG (8 or 16 bits, values clamped to [0,1]) or EXR (32-bit float,
// unclamped), chosen by the extension of `path`.
Status write_image(const Image& image, const std::string& path, int png_bits = 8);

// Reads any OpenImageIO format as float pixels; an image of more than
// `max_pixels` pixels (when positive) is an error, found before its
// pixels are read.
Result<Image> read_image(const std::string& path, long long max_pixels = 0);

}  // namespace shadetree
