// Files a graph names (meshes, images) are found relative to the graph
// file's folder. A path that leaves that folder is refused unless it lies
// under a folder the user allowed (--search-path): opening a graph from
// someone else must not read arbitrary files of the user.
#pragma once

#include <string>
#include <vector>

#include "graph/diagnostic.h"

namespace shadetree {

// The file `path` (as written in `graph_file`) names, or why it may not be
// read: it lies outside the graph's folder and `search_paths`, or it is
// there but not a regular file (a pipe would block the reader). `what` names the field in messages, e.g. "scene object #2 file".
Result<std::string> resolve_graph_resource(const std::string& graph_file, const std::string& path,
                                           const std::vector<std::string>& search_paths, const std::string& what);

}  // namespace shadetree
