// A signed distance field on a regular grid, negative inside: what a mesh
// becomes for the mesh ops (Gilet & Dischler 2010 section 5: arbitrary
// objects hypertextured as volumes, from a 64^3 grid as in the paper).
#pragma once

#include <array>
#include <vector>

namespace shadetree {

struct DistanceGrid {
  std::array<int, 3> size{0, 0, 0};
  std::array<float, 3> origin{0.0f, 0.0f, 0.0f};  // voxel (i, j, k) is centred at origin + ((i, j, k) + 0.5) * voxel_size
  float voxel_size = 0.0f;
  std::vector<float> distance;  // [(k * size[1] + j) * size[0] + i]
};

}  // namespace shadetree
