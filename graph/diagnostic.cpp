#include "graph/diagnostic.h"

namespace shadetree {

std::string Diagnostic::to_string() const {
  std::string line = "error: ";
  if (!file.empty()) line += file + ": ";
  if (!node.empty()) line += "node \"" + node + "\" ";
  if (!input.empty()) line += "input \"" + input + "\"";
  if (!node.empty() || !input.empty()) {
    if (line.back() == ' ') line.pop_back();
    line += ": ";
  }
  line += message;
  return line;
}

Diagnostic invalid_input(std::string message) {
  return Diagnostic{ExitStatus::invalid_input, {}, {}, {}, std::move(message)};
}

Diagnostic failure(std::string message) {
  return Diagnostic{ExitStatus::failure, {}, {}, {}, std::move(message)};
}

}  // namespace shadetree
