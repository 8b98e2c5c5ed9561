// Samples of a volume on a regular grid, as voxelize (render/voxelize.h)
// makes them and the VDB writer (io/vdb_file.h) takes them.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace shadetree {

// Cubic voxels of side `voxel_size`; voxel (i, j, k) is centred at
// origin + ((i, j, k) + 0.5) * voxel_size. Densities and colours are
// indexed [(k * size[1] + j) * size[0] + i].
struct VoxelGrid {
  std::array<int, 3> size{0, 0, 0};
  std::array<float, 3> origin{0.0f, 0.0f, 0.0f};
  float voxel_size = 0.0f;
  std::vector<float> density;
  std::vector<float> color;  // rgb per voxel; empty when the graph has no colour

  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * size[1] + j) * size[0] + i;
  }
};

}  // namespace shadetree
