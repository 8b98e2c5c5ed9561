#include "render/graph_files.h"

#include "nodes/limits.h"
#include "render/image_output.h"
#include "render/mesh.h"
#include "render/resource_path.h"
#include "render/vdb_file.h"

namespace shadetree {

GraphFiles graph_files(std::vector<std::string> search_paths) {
  GraphFiles files;
  files.image = [search_paths](const std::string& graph_file, const std::string& path) -> Result<Image> {
    Result<std::string> resolved = resolve_graph_resource(graph_file, path, search_paths, "image");
    if (!resolved) return resolved.error();
    Result<Image> image = read_image(*resolved, max_image_pixels);
    if (!image) return invalid_input(image.error().message);
    return image;
  };
  files.distance_grid = [search_paths](const std::string& graph_file, const std::string& path,
                                       int resolution) -> Result<DistanceGrid> {
    Result<std::string> resolved = resolve_graph_resource(graph_file, path, search_paths, "mesh");
    if (!resolved) return resolved.error();
    Result<TriangleMesh> mesh = load_mesh(*resolved);
    if (!mesh) return mesh.error();
    return mesh_distance_grid(*mesh, resolution);
  };
  return files;
}

}  // namespace shadetree
