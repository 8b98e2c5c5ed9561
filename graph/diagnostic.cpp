#include "graph/diagnostic.h"

namespace shadetree {
namespace {

// A diagnostic echoes what the user wrote, which may be a 4 MB node id:
// each name and the whole line are cut to these lengths.
constexpr std::size_t max_name_shown = 200, max_line_shown = 1000;

std::string shortened(const std::string& text, std::size_t limit) {
  if (text.size() <= limit) return text;
  return text.substr(0, limit) + "... (" + std::to_string(text.size() - limit) + " more bytes)";
}

}  // namespace

std::string printable(const std::string& text) {
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

std::string Diagnostic::to_string() const {
  std::string line = "error: ";
  if (!file.empty()) line += shortened(file, max_name_shown) + ": ";
  if (!node.empty()) line += "node \"" + shortened(node, max_name_shown) + "\" ";
  // Without a node, `input` names what is at fault as it is (output "color").
  if (!input.empty())
    line += node.empty() ? shortened(input, max_name_shown) : "input \"" + shortened(input, max_name_shown) + "\"";
  if (!node.empty() || !input.empty()) {
    if (line.back() == ' ') line.pop_back();
    line += ": ";
  }
  line += message;
  return shortened(printable(line), max_line_shown);
}

Diagnostic invalid_input(std::string message) {
  return Diagnostic{ExitStatus::invalid_input, {}, {}, {}, std::move(message)};
}

Diagnostic failure(std::string message) {
  return Diagnostic{ExitStatus::failure, {}, {}, {}, std::move(message)};
}

}  // namespace shadetree
