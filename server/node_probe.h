// A picture of one node, for the editor's node thumbnails: the graph with
// its outputs replaced by that node's value. Texture and surface graphs
// show the value as their colour (a float as grey, a vec2 as red and
// green, a vec3 as its three components, a bool as white where true);
// a kind whose driver says so rewrites that graph (a volume shows the
// value on a slice through its bounds: render/volume_driver.h). Only the
// node and the nodes it reads are kept.
#pragma once

#include <string>

#include "graph/check.h"
#include "graph/diagnostic.h"

namespace shadetree {

// The probe graph's JSON text, for graph text `json` (named `file` in
// messages) and `node`, a node id of the main graph or "id.output". With
// `function`, `node` is a node of that function's body, shown as it is
// at the function's first call in the main graph.
Result<std::string> node_probe_graph(const std::string& json, const std::string& file, const std::string& node,
                                     const GraphFiles& files, const std::string& function = "");

}  // namespace shadetree
