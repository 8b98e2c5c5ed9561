#include "jit/kernel_object_cache.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <vector>

namespace shadetree {

std::filesystem::path kernel_cache_folder(const std::string& configured) {
  if (!configured.empty()) return configured;
  if (const char* folder = std::getenv("SHADETREE_CACHE_DIR"); folder && *folder) return folder;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "shadetree";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "shadetree";
  return {};
}

namespace {

// Keeps `folder` to `limit` kernel objects, removing the least recently
// used (written, or read: compile() touches what it reads) first: an
// editor session compiles a program per edit.
void prune_objects(const std::filesystem::path& folder, int limit) {
  std::error_code error;
  std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> objects;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("shade_kernel_") && entry.path().extension() == ".o")
      objects.emplace_back(entry.last_write_time(error), entry.path());
  }
  const std::size_t keep = static_cast<std::size_t>(std::max(limit, 0));
  if (objects.size() <= keep) return;
  std::sort(objects.begin(), objects.end());
  for (std::size_t i = 0; i + keep < objects.size(); ++i) std::filesystem::remove(objects[i].second, error);
}

}  // namespace

void store_kernel_object(const std::filesystem::path& folder, const std::string& name, std::string_view object,
                         int limit) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  static std::atomic<long> writes{0};  // two threads of a process may store the same kernel
  const auto target = folder / (name + ".o");
  const auto temporary = folder / (name + ".o.partial-" + std::to_string(static_cast<long>(::getpid())) + "-" +
                                   std::to_string(++writes));
  std::ofstream file(temporary, std::ios::binary);
  file.write(object.data(), static_cast<std::streamsize>(object.size()));
  file.close();
  if (!file) {
    std::filesystem::remove(temporary, error);
    return;
  }
  std::filesystem::rename(temporary, target, error);
  if (error) std::filesystem::remove(temporary, error);
  prune_objects(folder, limit);
}

}  // namespace shadetree
