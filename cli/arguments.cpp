#include "cli/arguments.h"

#include <cmath>
#include <sstream>

namespace shadetree {

Result<std::pair<int, int>> parse_size(const std::string& text) {
  int width = 0, height = 0;
  char separator = 0, trailing = 0;
  std::istringstream stream(text);
  if (!(stream >> width >> separator >> height) || separator != 'x' || (stream >> trailing))
    return invalid_input("--size expects WIDTHxHEIGHT, got \"" + text + "\"");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    return invalid_input("--size " + text + ": each side must be between 1 and 16384 pixels");
  return std::pair{width, height};
}

Result<std::vector<float>> parse_floats(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<float> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(value)) break;
    values.push_back(static_cast<float>(value));
  }
  if (values.size() != count)
    return invalid_input(what + " expects " + std::to_string(count) + " comma-separated numbers, got \"" + text + "\"");
  return values;
}

}  // namespace shadetree
