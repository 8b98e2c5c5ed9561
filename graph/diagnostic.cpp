#include "graph/diagnostic.h"

namespace shadetree {
namespace {

// Names and messages echo what the user wrote; a newline in a node id must
// not split the line, nor a NUL end it.
std::string escaped(const std::string& text) {
  std::string result;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      result += "\\n";
    } else if (c == '\t') {
      result += "\\t";
    } else if (c == '\r') {
      result += "\\r";
    } else if (byte < 0x20 || byte == 0x7f) {
      constexpr char hex[] = "0123456789abcdef";
      result += "\\x";
      result += hex[byte >> 4];
      result += hex[byte & 15];
    } else {
      result += c;
    }
  }
  return result;
}

}  // namespace

std::string Diagnostic::to_string() const {
  std::string line = "error: ";
  if (!file.empty()) line += file + ": ";
  if (!node.empty()) line += "node \"" + node + "\" ";
  // Without a node, `input` names what is at fault as it is (output "color").
  if (!input.empty()) line += node.empty() ? input : "input \"" + input + "\"";
  if (!node.empty() || !input.empty()) {
    if (line.back() == ' ') line.pop_back();
    line += ": ";
  }
  line += message;
  return escaped(line);
}

Diagnostic invalid_input(std::string message) {
  return Diagnostic{ExitStatus::invalid_input, {}, {}, {}, std::move(message)};
}

Diagnostic failure(std::string message) {
  return Diagnostic{ExitStatus::failure, {}, {}, {}, std::move(message)};
}

}  // namespace shadetree
