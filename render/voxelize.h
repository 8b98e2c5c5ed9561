// A volume graph sampled on a regular grid over its bounds, for export
// (render/vdb_file.h), so that a hypertexture opens in Blender or Houdini.
#pragma once

#include <array>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/scene.h"
#include "ir/kernel.h"
#include "render/progress.h"

namespace shadetree {

// Voxels along the bounds' longest side, at most: 512^3 voxels hold 0.5 GiB
// of densities and 1.5 GiB of colours before they are written.
inline constexpr int max_voxel_resolution = 512;

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

struct VoxelizeOptions {
  int resolution = 128;  // voxels along the longest side of the bounds
  float frame = 0.0f;
  int threads = 0;  // 0: all cores
  ProgressCallback progress;  // slices of the grid, voxels
};

// The graph's density (and colour) at every voxel centre, a slice at a
// time through one kernel call; step_size and filter_width are the voxel
// size, so that frequency clamping matches the grid.
Result<VoxelGrid> voxelize(const Kernel& kernel, const std::vector<float>& params, const VolumeDesc& volume,
                           const VoxelizeOptions& options);

}  // namespace shadetree
