// Files made up from their names, for tests of the ops that read files
// without touching the disk:
// - images: "4x2x3.png" is 4 x 2 pixels of 3 channels, channel c of the
//   pixel in column i and row j (from the top) being (i + 10 j + 100 c) / 1000;
// - meshes: any name is a sphere of radius 0.8 at the origin, as a distance
//   grid over [-1.2, 1.2]^3.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "graph/check.h"
#include "pipeline/compile_graph.h"
#include "graph_text.h"

namespace shadetree::testing {

inline float test_image_value(int column, int row, int channel) {
  return static_cast<float>(column + 10 * row + 100 * channel) / 1000.0f;
}

inline constexpr float test_mesh_radius = 0.8f;

inline GraphFiles test_files() {
  GraphFiles files;
  files.image = [](const std::string&, const std::string& path) -> Result<Image> {
    Image image;
    if (std::sscanf(path.c_str(), "%dx%dx%d", &image.width, &image.height, &image.channels) != 3)
      return invalid_input("no test image \"" + path + "\"");
    for (int row = 0; row < image.height; ++row)
      for (int column = 0; column < image.width; ++column)
        for (int c = 0; c < image.channels; ++c) image.pixels.push_back(test_image_value(column, row, c));
    return image;
  };
  files.distance_grid = [](const std::string&, const std::string&, int resolution) -> Result<DistanceGrid> {
    DistanceGrid grid;
    grid.size = {resolution, resolution, resolution};
    grid.origin = {-1.2f, -1.2f, -1.2f};
    grid.voxel_size = 2.4f / static_cast<float>(resolution);
    for (int k = 0; k < resolution; ++k)
      for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i) {
          const float x = -1.2f + (i + 0.5f) * grid.voxel_size, y = -1.2f + (j + 0.5f) * grid.voxel_size,
                      z = -1.2f + (k + 0.5f) * grid.voxel_size;
          grid.distance.push_back(std::sqrt(x * x + y * y + z * z) - test_mesh_radius);
        }
    return grid;
  };
  return files;
}

// A texture graph whose node "photo" reads a 1024x1024 RGBA image, in a
// file "big.json": more data than an emitter writes as source.
inline Result<LoadedGraph> large_image_graph() {
  return compile_graph_text(graph_text(R"({"id": "uv", "op": "uv"}, {"id": "photo", "op": "image", "in": {"uv": "uv"},
                                         "file": "1024x1024x4.png"})",
                                       R"("color": "photo")"),
                            "big.json", {}, {}, test_files());
}

}  // namespace shadetree::testing
