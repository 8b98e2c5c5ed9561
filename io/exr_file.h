// OpenEXR files through the OpenEXR library, without OpenImageIO (see
// io/png_file.h for why).
#pragma once

#include <string>

#include "nodes/image.h"

namespace shadetree {

// Writes `image` to `file` as 32-bit float channels (Y for one channel,
// else R, G, B, A, channel4...), ZIP-compressed, unclamped. The header records
// the software and the time of writing (capDate), which is the time
// SOURCE_DATE_EPOCH gives when set, so that renders can be reproducible to
// the byte. Returns why it could not, or "".
std::string write_exr(const Image& image, const std::string& file);

}  // namespace shadetree
