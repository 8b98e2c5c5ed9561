// "1, 2.5,3" -> {1, 2.5, 3}: the comma-separated numbers of --set values and
// of command-line points. Empty if any item is not a finite float.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace shadetree {

std::optional<std::vector<float>> parse_number_list(const std::string& text);

}  // namespace shadetree
