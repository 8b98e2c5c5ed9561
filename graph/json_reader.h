// Typed fields out of a parsed graph document. Parsing stops at the first
// error: fail() throws a ParseError that parse_graph turns back into a
// value, so every reader names the file and, where known, the node.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "graph/diagnostic.h"

namespace shadetree {

// ordered_json keeps objects in file order: a function's first output is
// the first one written.
using json = nlohmann::ordered_json;

struct ParseError {
  Diagnostic diagnostic;
};

class JsonReader {
 public:
  explicit JsonReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& node, const std::string& input, const std::string& message) const;

  std::string required_string(const json& object, const char* key, const std::string& node) const;
  std::string optional_string(const json& object, const char* key, const std::string& node,
                              std::string fallback) const;

  // A finite number within float range.
  float number(const json& value, const std::string& node, const std::string& what) const;
  // A number, or an array of numbers.
  std::vector<float> numbers(const json& value, const std::string& node, const std::string& what) const;

 private:
  std::string file_;
};

}  // namespace shadetree
