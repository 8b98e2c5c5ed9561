// The files a graph's ops name, read from the graph's folder or a folder
// the user allowed (--search-path), as scene meshes are
// (io/resource_path.h): images for the `image` op (OpenImageIO), mesh
// files as signed distance grids for the mesh ops (Assimp, then OpenVDB).
#pragma once

#include <string>
#include <vector>

#include "graph/check.h"

namespace shadetree {

// The readers keep what they have read, until the file changes on disk:
// one GraphFiles may serve many checks (shadetree serve keeps one).
GraphFiles graph_files(std::vector<std::string> search_paths = {});

}  // namespace shadetree
