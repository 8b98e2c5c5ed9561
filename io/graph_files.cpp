#include "io/graph_files.h"

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <utility>

#include "nodes/limits.h"
#include "io/distance_grid_cache.h"
#include "io/image_output.h"
#include "io/mesh_file.h"
#include "io/resource_path.h"
#include "io/vdb_file.h"
#include "platform/user_cache.h"

namespace shadetree {
namespace {

// What the readers of one GraphFiles have read, by resolved path (and grid
// resolution), with the file's modification time: a graph that names a
// file in several nodes (a mesh's distance and closest point, say) reads
// and converts it once, and a file changed on disk is read again. Only
// what was read without error is kept.
template <class Key, class Value>
class ReadCache {
 public:
  template <class Read>
  Result<Value> get(const Key& key, const std::string& path, Read read) {
    std::error_code error;
    const auto time = std::filesystem::last_write_time(path, error);
    std::lock_guard lock(mutex_);
    auto found = entries_.find(key);
    if (found != entries_.end() && !error && found->second.first == time) return found->second.second;
    Result<Value> value = read();
    if (value && !error) entries_.insert_or_assign(key, std::pair{time, *value});
    return value;
  }

 private:
  std::mutex mutex_;
  std::map<Key, std::pair<std::filesystem::file_time_type, Value>> entries_;
};

struct ReadFiles {
  ReadCache<std::string, Image> images;
  ReadCache<std::pair<std::string, int>, DistanceGrid> grids;
};

}  // namespace

GraphFiles graph_files(std::vector<std::string> search_paths) {
  auto read = std::make_shared<ReadFiles>();
  GraphFiles files;
  files.image = [search_paths, read](const std::string& graph_file, const std::string& path) -> Result<Image> {
    Result<std::string> resolved = resolve_graph_resource(graph_file, path, search_paths, "image");
    if (!resolved) return resolved.error();
    return read->images.get(*resolved, *resolved, [&]() -> Result<Image> {
      Result<Image> image = read_image(*resolved, max_image_pixels);
      if (!image) return invalid_input(image.error().message);
      return image;
    });
  };
  files.distance_grid = [search_paths, read](const std::string& graph_file, const std::string& path,
                                             int resolution) -> Result<DistanceGrid> {
    Result<std::string> resolved = resolve_graph_resource(graph_file, path, search_paths, "mesh");
    if (!resolved) return resolved.error();
    return read->grids.get(std::pair{*resolved, resolution}, *resolved, [&]() -> Result<DistanceGrid> {
      std::error_code unresolved;
      const DistanceGridSource source{std::filesystem::absolute(*resolved, unresolved), resolution};
      const std::filesystem::path folder = user_cache_folder("");
      if (std::optional<DistanceGrid> cached = read_cached_distance_grid(folder, source)) return std::move(*cached);
      Result<TriangleMesh> mesh = load_mesh(*resolved);
      if (!mesh) return mesh.error();
      Result<DistanceGrid> grid = mesh_distance_grid(*mesh, resolution);
      if (grid) {
        store_distance_grid(folder, source, *grid);
        return grid;
      }
      Diagnostic error = grid.error();
      error.file = *resolved;
      return error;
    });
  };
  return files;
}

}  // namespace shadetree
