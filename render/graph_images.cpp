#include "render/graph_images.h"

#include "nodes/limits.h"
#include "render/image_output.h"
#include "render/resource_path.h"

namespace shadetree {

ImageReader graph_image_reader(std::vector<std::string> search_paths) {
  return [search_paths = std::move(search_paths)](const std::string& graph_file,
                                                  const std::string& path) -> Result<Image> {
    Result<std::string> resolved = resolve_graph_resource(graph_file, path, search_paths, "image");
    if (!resolved) return resolved.error();
    Result<Image> image = read_image(*resolved, max_image_pixels);
    if (!image) return invalid_input(image.error().message);
    return image;
  };
}

}  // namespace shadetree
