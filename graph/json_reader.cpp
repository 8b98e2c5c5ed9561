#include "graph/json_reader.h"

#include <cmath>

namespace shadetree {

void JsonReader::fail(const std::string& node, const std::string& input, const std::string& message) const {
  throw ParseError{Diagnostic{ExitStatus::invalid_input, file_, node, input, message}};
}

std::string JsonReader::required_string(const json& object, const char* key, const std::string& node) const {
  if (!object.contains(key)) fail(node, {}, std::string("missing field \"") + key + "\"");
  if (!object[key].is_string()) fail(node, {}, std::string("field \"") + key + "\" must be a string");
  return object[key].get<std::string>();
}

std::string JsonReader::optional_string(const json& object, const char* key, const std::string& node,
                                        std::string fallback) const {
  if (!object.contains(key)) return fallback;
  return required_string(object, key, node);
}

float JsonReader::number(const json& value, const std::string& node, const std::string& what) const {
  if (!value.is_number()) fail(node, {}, what + " must be a number");
  const double number = value.get<double>();
  if (!std::isfinite(number) || std::fabs(number) > 3.4e38)
    fail(node, {}, what + " is out of the range of a 32-bit float");
  return static_cast<float>(number);
}

std::vector<float> JsonReader::numbers(const json& value, const std::string& node, const std::string& what) const {
  if (value.is_number()) return {number(value, node, what)};
  if (!value.is_array()) fail(node, {}, what + " must be a number or an array of numbers");
  std::vector<float> result;
  for (const json& item : value) result.push_back(number(item, node, what + " item"));
  return result;
}

}  // namespace shadetree
