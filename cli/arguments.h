// Parsing of command-line values shared by several commands.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <optional>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "render/texture_driver.h"

namespace shadetree {

// "512x256" -> {512, 256}, within the image size limit.
Result<std::pair<int, int>> parse_size(const std::string& text);

// "1,2,3" -> three floats.
Result<std::vector<float>> parse_floats(const std::string& text, std::size_t count, const std::string& what);

// The texture view of a graph's render settings with --size and --frame
// applied (empty size / no frame: keep the graph's).
Result<TextureView> texture_view(const Graph& graph, const std::string& size, std::optional<float> frame);

}  // namespace shadetree
