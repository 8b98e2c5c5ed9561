// A volume graph sampled on a regular grid over its bounds, for export
// (io/vdb_file.h), so that a hypertexture opens in Blender or Houdini.
#pragma once

#include <vector>

#include "graph/diagnostic.h"
#include "graph/scene.h"
#include "ir/kernel.h"
#include "io/voxel_grid.h"
#include "schedule/progress.h"

namespace shadetree {

// Voxels along the bounds' longest side, at most: 512^3 voxels hold 0.5 GiB
// of densities and 1.5 GiB of colours before they are written.
inline constexpr int max_voxel_resolution = 512;

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
