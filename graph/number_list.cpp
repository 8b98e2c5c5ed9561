#include "graph/number_list.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace shadetree {

std::optional<std::vector<float>> parse_number_list(const std::string& text) {
  std::vector<float> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(value) || std::fabs(value) > 3.4e38) return std::nullopt;
    values.push_back(static_cast<float>(value));
  }
  if (values.empty()) return std::nullopt;
  return values;
}

}  // namespace shadetree
