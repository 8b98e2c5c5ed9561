// Load -> parse -> check -> lower, plus --set overrides: what every command
// that runs a graph does first.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "graph/shade_ir.h"

namespace shadetree {

struct LoadedGraph {
  std::shared_ptr<const Graph> graph;
  ShadeIR ir;
  std::vector<float> params;  // the uniform block, --set values applied
};

// `assignments` are NAME=VALUE strings from --set.
Result<LoadedGraph> load_and_compile(const std::string& path, const std::vector<std::string>& assignments);

// "512x256" -> {512, 256}, within the image size limit.
Result<std::pair<int, int>> parse_size(const std::string& text);

// "1,2,3" -> three floats.
Result<std::vector<float>> parse_floats(const std::string& text, std::size_t count, const std::string& what);

}  // namespace shadetree
