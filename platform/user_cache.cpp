#include "platform/user_cache.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <utility>
#include <vector>

namespace shadetree {

std::filesystem::path user_cache_folder(const std::string& configured) {
  if (!configured.empty()) return configured;
  if (const char* folder = std::getenv("SHADETREE_CACHE_DIR"); folder && *folder) return folder;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "shadetree";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "shadetree";
  return {};
}

namespace {

// Keeps `folder` to `limit` files of a kind, removing the least recently
// used first: an editor session compiles a program per edit.
void prune(const std::filesystem::path& folder, const std::string& kind, const std::filesystem::path& extension,
           int limit) {
  std::error_code error;
  std::vector<std::pair<std::filesystem::file_time_type, std::filesystem::path>> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(kind) && entry.path().extension() == extension)
      files.emplace_back(entry.last_write_time(error), entry.path());
  }
  const std::size_t keep = static_cast<std::size_t>(std::max(limit, 0));
  if (files.size() <= keep) return;
  std::sort(files.begin(), files.end());
  for (std::size_t i = 0; i + keep < files.size(); ++i) std::filesystem::remove(files[i].second, error);
}

}  // namespace

void store_in_cache(const std::filesystem::path& folder, const std::string& name, std::string_view bytes,
                    const std::string& kind, int limit) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  static std::atomic<long> writes{0};  // two threads of a process may store the same file
  const auto target = folder / name;
  const auto temporary =
      folder / (name + ".partial-" + std::to_string(static_cast<long>(::getpid())) + "-" + std::to_string(++writes));
  std::ofstream file(temporary, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.close();
  if (!file) {
    std::filesystem::remove(temporary, error);
    return;
  }
  std::filesystem::rename(temporary, target, error);
  if (error) std::filesystem::remove(temporary, error);
  prune(folder, kind, target.extension(), limit);
}

}  // namespace shadetree
