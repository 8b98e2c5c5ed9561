#include "graph/file_path.h"

#include "graph/generated_names.h"

namespace shadetree {

Status check_path_text(const std::string& path, const std::string& what) {
  const auto refuse = [&](const std::string& problem) -> Status {
    return invalid_input(what + " " + quoted_text(path, 120) + ": " + problem);
  };
  if (path.empty()) return refuse("empty path");
  if (path.size() > max_path_bytes) return refuse("path longer than " + std::to_string(max_path_bytes) + " bytes");
  std::size_t name_start = 0;
  for (std::size_t i = 0; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/') {
      if (i - name_start > max_file_name_bytes)
        return refuse("a name in the path is longer than " + std::to_string(max_file_name_bytes) + " bytes");
      name_start = i + 1;
      continue;
    }
    const auto byte = static_cast<unsigned char>(path[i]);
    if (byte == 0) return refuse("path holds a NUL byte");
    if (byte < 0x20 || byte == 0x7f) return refuse("path holds a control character");
  }
  return success();
}

}  // namespace shadetree
