// The gallery graphs, for tests that run over all of them.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "graph/parse.h"
#include "pipeline/compile_graph.h"
#include "io/graph_files.h"

namespace shadetree::testing {

inline std::vector<std::string> gallery_graphs() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(SHADETREE_SOURCE_DIR "/graphs"))
    if (entry.path().extension() == ".json") paths.push_back(entry.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

// The gallery graphs of one kind.
inline std::vector<std::string> gallery_graphs(GraphKind kind) {
  std::vector<std::string> paths;
  for (const std::string& path : gallery_graphs()) {
    Result<Graph> graph = load_graph(path);
    if (graph && graph->kind == kind) paths.push_back(path);
  }
  return paths;
}

// A gallery graph compiled as `shadetree render` compiles it (the files it
// names read from its folder); `observe` as in load_and_compile.
inline Result<LoadedGraph> load_gallery_graph(const std::string& path, const PassObserver& observe = {}) {
  return load_and_compile(path, {}, observe, graph_files());
}

// Test names from paths: "graphs/marble.json" -> "marble".
inline std::string gallery_graph_name(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace shadetree::testing
