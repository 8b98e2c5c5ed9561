#include "graph/number_list.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace shadetree {

std::optional<std::vector<float>> parse_number_list(const std::string& text) {
  // Plain decimal numbers only: strtod alone would also take leading
  // spaces, hex and "inf".
  if (text.empty() || text.back() == ',') return std::nullopt;
  std::vector<float> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (item.empty() || item.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value) || std::fabs(value) > 3.4e38) return std::nullopt;
    values.push_back(static_cast<float>(value));
  }
  return values;
}

}  // namespace shadetree
