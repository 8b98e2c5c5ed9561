// Parsing of command-line values shared by several commands.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "graph/diagnostic.h"

namespace shadetree {

// "512x256" -> {512, 256}, within the image size limit.
Result<std::pair<int, int>> parse_size(const std::string& text);

// "1,2,3" -> three floats.
Result<std::vector<float>> parse_floats(const std::string& text, std::size_t count, const std::string& what);

}  // namespace shadetree
