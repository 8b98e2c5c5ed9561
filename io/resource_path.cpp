#include "io/resource_path.h"

#include <filesystem>

#include "graph/file_path.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

// Whether `path` is `folder` or lies below it; both already canonical.
bool lies_under(const fs::path& path, const fs::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (f->empty()) continue;  // a trailing separator
    if (p == path.end() || *p != *f) return false;
  }
  return true;
}

}  // namespace

Result<std::string> resolve_graph_resource(const std::string& graph_file, const std::string& path,
                                           const std::vector<std::string>& search_paths, const std::string& what) {
  if (Status text = check_path_text(path, what); !text) {
    Diagnostic refused = text.error();
    refused.file = graph_file;
    return refused;
  }
  std::error_code error;
  // A graph named without a folder ("g.json") lies in the current one; an
  // empty folder would make every path lie "under" it.
  fs::path folder = fs::path(graph_file).parent_path();
  if (folder.empty()) folder = ".";
  const fs::path graph_folder = fs::weakly_canonical(fs::absolute(folder, error), error);
  if (error) return Diagnostic{ExitStatus::invalid_input, graph_file, {}, {}, what + " \"" + path + "\": " + error.message()};
  const fs::path written(path);
  const fs::path resolved =
      fs::weakly_canonical(written.is_absolute() ? written : graph_folder / written, error);
  if (error) return Diagnostic{ExitStatus::invalid_input, graph_file, {}, {}, what + " \"" + path + "\": " + error.message()};
  bool allowed = lies_under(resolved, graph_folder);
  for (const std::string& folder : search_paths)
    allowed = allowed || lies_under(resolved, fs::weakly_canonical(fs::absolute(folder, error), error));
  if (!allowed)
    return Diagnostic{ExitStatus::invalid_input, graph_file, {}, {},
                      what + " \"" + path + "\" lies outside the graph's folder (allow its folder with --search-path)"};
  // A pipe or a device would block the reader, or never end: only files
  // (a missing one is left to the reader to name).
  const fs::file_status status = fs::status(resolved, error);
  if (fs::exists(status) && !fs::is_regular_file(status))
    return Diagnostic{ExitStatus::invalid_input, graph_file, {}, {},
                      what + " \"" + path + "\" is not a regular file"};
  return resolved.string();
}

}  // namespace shadetree
