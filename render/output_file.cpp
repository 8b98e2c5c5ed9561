#include "render/output_file.h"

#include <unistd.h>

#include <filesystem>

namespace shadetree {

Status check_output_folder(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!folder.empty() && !std::filesystem::is_directory(folder, error))
    return failure("output \"" + path + "\": folder \"" + folder.string() + "\" does not exist");
  return success();
}

Status write_then_rename(const std::string& path, const std::function<std::string(const std::string&)>& write) {
  const std::filesystem::path target(path);
  const std::filesystem::path temporary = target.parent_path() / ("." + target.filename().string() + ".partial-" +
                                                                   std::to_string(::getpid()) +
                                                                   target.extension().string());
  const std::string problem = write(temporary.string());
  std::error_code error;
  if (!problem.empty()) {
    std::filesystem::remove(temporary, error);
    return failure("output \"" + path + "\": " + problem);
  }
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return failure("output \"" + path + "\": cannot rename the finished file into place");
  }
  return success();
}

}  // namespace shadetree
