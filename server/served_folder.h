// The folder `shadetree serve` serves: the graph files under it, and the
// one rule for every path a request names, which must stay inside it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "graph/diagnostic.h"

namespace shadetree {

class ServedFolder {
 public:
  // `folder` must exist; it is made canonical (symlinks resolved).
  static Result<ServedFolder> open(const std::string& folder);

  // The file `relative` names inside the folder, or why not: a path the
  // path policy refuses (graph/file_path.h: empty, NUL, control
  // characters, over-long names), an absolute path, a ".." component, or a
  // path that leaves the folder through a symlink. Files need not exist (a save may create one), but
  // their folder must.
  Result<std::filesystem::path> resolve(const std::string& relative) const;

  // The .json files under the folder, relative to it, sorted.
  std::vector<std::string> graph_files() const;

  const std::filesystem::path& path() const { return root_; }

  // `text` with the folder's path taken off every path it begins (at the
  // start of the text, or after a space, quote or bracket), so that a
  // message names files as the page does and does not show where the
  // folder is on the server's disk.
  std::string relative_text(std::string text) const;

 private:
  std::filesystem::path root_;
};

}  // namespace shadetree
