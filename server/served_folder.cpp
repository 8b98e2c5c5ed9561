#include "server/served_folder.h"

#include <algorithm>
#include <string_view>

#include "graph/file_path.h"

namespace shadetree {

namespace fs = std::filesystem;

Result<ServedFolder> ServedFolder::open(const std::string& folder) {
  std::error_code error;
  fs::path root = fs::canonical(folder, error);
  if (error || !fs::is_directory(root, error))
    return Diagnostic{ExitStatus::invalid_input, folder, {}, {}, "not a folder that can be served"};
  ServedFolder served;
  served.root_ = root;
  return served;
}

std::string ServedFolder::relative_text(std::string text) const {
  const std::string root = (root_ / "").string();
  for (std::size_t at = 0; (at = text.find(root, at)) != std::string::npos;) {
    if (at == 0 || std::string_view(" \"'(").find(text[at - 1]) != std::string_view::npos)
      text.erase(at, root.size());
    else
      at += root.size();
  }
  return text;
}

Result<fs::path> ServedFolder::resolve(const std::string& relative) const {
  // The path policy first: the system would see "ocean.png\0.json" as
  // ocean.png, which a ".json" rule checked on the whole text lets through.
  if (Status text = check_path_text(relative, "path"); !text) return text.error();
  const fs::path path(relative);
  if (path.is_absolute())
    return invalid_input("\"" + relative + "\": expected a path relative to the served folder");
  for (const fs::path& part : path)
    if (part == "..") return invalid_input("\"" + relative + "\": \"..\" may not leave the served folder");
  std::error_code error;
  const fs::path parent = fs::canonical((root_ / path).parent_path(), error);
  if (error) return invalid_input("\"" + relative + "\": no such folder in the served folder");
  fs::path resolved = parent / path.filename();
  std::error_code link_error;
  if (fs::is_symlink(resolved, link_error)) {
    resolved = fs::canonical(resolved, link_error);
    if (link_error) return invalid_input("\"" + relative + "\" is a broken link");
  }
  const auto [end, unused] = std::mismatch(root_.begin(), root_.end(), resolved.begin(), resolved.end());
  if (end != root_.end()) return invalid_input("\"" + relative + "\" lies outside the served folder");
  return resolved;
}

std::vector<std::string> ServedFolder::graph_files() const {
  std::vector<std::string> files;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(root_, fs::directory_options::skip_permission_denied, error);
       !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (!it->is_regular_file(error) || it->path().extension() != ".json") continue;
    const std::string relative = it->path().lexically_relative(root_).generic_string();
    if (resolve(relative)) files.push_back(relative);  // not links out of the folder
    if (files.size() >= 10000) break;
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace shadetree
