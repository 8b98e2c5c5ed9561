#include "render/graph_files.h"

#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "nodes/limits.h"
#include "render/image_output.h"
#include "render/mesh.h"
#include "render/resource_path.h"
#include "render/vdb_file.h"

namespace shadetree {
namespace {

// What the readers of one GraphFiles have read, by resolved path (and grid
// resolution): a graph that names a file in several nodes (a mesh's
// distance and closest point, say) reads and converts it once.
struct ReadFiles {
  std::mutex mutex;
  std::map<std::string, Result<Image>> images;
  std::map<std::pair<std::string, int>, Result<DistanceGrid>> grids;
};

}  // namespace

GraphFiles graph_files(std::vector<std::string> search_paths) {
  auto read = std::make_shared<ReadFiles>();
  GraphFiles files;
  files.image = [search_paths, read](const std::string& graph_file, const std::string& path) -> Result<Image> {
    Result<std::string> resolved = resolve_graph_resource(graph_file, path, search_paths, "image");
    if (!resolved) return resolved.error();
    std::lock_guard lock(read->mutex);
    auto found = read->images.find(*resolved);
    if (found == read->images.end()) {
      Result<Image> image = read_image(*resolved, max_image_pixels);
      if (!image) image = invalid_input(image.error().message);
      found = read->images.emplace(*resolved, std::move(image)).first;
    }
    return found->second;
  };
  files.distance_grid = [search_paths, read](const std::string& graph_file, const std::string& path,
                                             int resolution) -> Result<DistanceGrid> {
    Result<std::string> resolved = resolve_graph_resource(graph_file, path, search_paths, "mesh");
    if (!resolved) return resolved.error();
    std::lock_guard lock(read->mutex);
    const auto key = std::pair{*resolved, resolution};
    auto found = read->grids.find(key);
    if (found == read->grids.end()) {
      Result<TriangleMesh> mesh = load_mesh(*resolved);
      found = read->grids.emplace(key, mesh ? mesh_distance_grid(*mesh, resolution) : Result<DistanceGrid>(mesh.error()))
                  .first;
    }
    return found->second;
  };
  return files;
}

}  // namespace shadetree
