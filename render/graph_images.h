// The image files a graph samples (the `image` op), read with OpenImageIO
// from the graph's folder or a folder the user allowed (--search-path), as
// meshes are (render/resource_path.h).
#pragma once

#include <string>
#include <vector>

#include "graph/check.h"

namespace shadetree {

ImageReader graph_image_reader(std::vector<std::string> search_paths = {});

}  // namespace shadetree
