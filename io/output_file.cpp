#include "io/output_file.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>

#include "graph/file_path.h"

namespace shadetree {
namespace {

// A name in `target`'s folder that no other call uses, in this process
// (the counter) or another (the pid): concurrent saves of one file each
// write their own temporary. It keeps the target's extension and is cut to
// fit a file name, since the target's own may already be 255 bytes long.
std::filesystem::path temporary_name(const std::filesystem::path& target) {
  static std::atomic<unsigned long> calls{0};
  const std::string tag = ".partial-" + std::to_string(::getpid()) + "-" + std::to_string(++calls);
  std::string extension = target.extension().string();
  if (tag.size() + extension.size() + 1 > max_file_name_bytes) extension.clear();  // no format has such a name
  const std::size_t room = max_file_name_bytes - 1 - tag.size() - extension.size();
  const std::string stem = target.stem().string().substr(0, room);
  return target.parent_path() / ("." + stem + tag + extension);
}

}  // namespace

Status check_output_folder(const std::string& path) {
  if (Status text = check_path_text(path, "output"); !text) return text;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!folder.empty() && !std::filesystem::is_directory(folder, error))
    return failure("output \"" + path + "\": folder \"" + folder.string() + "\" does not exist");
  return success();
}

Status write_then_rename(const std::string& path, const std::function<std::string(const std::string&)>& write) {
  if (Status text = check_path_text(path, "output"); !text) return text;
  const std::filesystem::path target(path);
  const std::filesystem::path temporary = temporary_name(target);
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
