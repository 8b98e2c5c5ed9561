#include "render/voxelize.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "schedule/thread_arena.h"
#include "schedule/thread_bindings.h"
#include "render/volume_driver.h"

namespace shadetree {

Result<VoxelGrid> voxelize(const Kernel& kernel, const std::vector<float>& params, const VolumeDesc& volume,
                           const VoxelizeOptions& options) {
  const OutputLayout& layout = kernel.outputs();
  if (layout.kind != GraphKind::volume || !layout.provides(OutputId::density))
    return invalid_input("voxelize needs a volume graph with an output \"density\"");
  if (options.resolution < 1 || options.resolution > max_voxel_resolution)
    return invalid_input("--res must be from 1 to " + std::to_string(max_voxel_resolution));
  VoxelGrid grid;
  float longest = 0.0f;
  for (int axis = 0; axis < 3; ++axis) longest = std::max(longest, volume.bounds_max[axis] - volume.bounds_min[axis]);
  grid.voxel_size = longest / static_cast<float>(options.resolution);
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = volume.bounds_max[axis] - volume.bounds_min[axis];
    grid.size[axis] = std::clamp(static_cast<int>(std::ceil(extent / grid.voxel_size - 1e-4f)), 1, options.resolution);
    grid.origin[axis] = volume.bounds_min[axis];
  }
  const std::size_t slice = static_cast<std::size_t>(grid.size[0]) * grid.size[1];
  const bool colored = layout.provides(OutputId::color);
  grid.density.assign(slice * grid.size[2], 0.0f);
  if (colored) grid.color.assign(3 * slice * grid.size[2], 0.0f);

  ThreadBindings bindings(kernel, params.data(), volume_uniforms(options.frame, grid.voxel_size));
  std::atomic<int> slices_done{0};
  tbb::task_arena arena(arena_concurrency(options.threads));
  arena.execute([&] {
    tbb::parallel_for(0, grid.size[2], [&](int k) {
      SampleBuffers inputs(slice, kernel.reads());
      OutputBuffers outputs(slice, layout);
      for (int j = 0; j < grid.size[1]; ++j)
        for (int i = 0; i < grid.size[0]; ++i) {
          const std::size_t s = static_cast<std::size_t>(j) * grid.size[0] + i;
          const int voxel[3] = {i, j, k};
          if (inputs.has(GlobalId::P))
            for (int c = 0; c < 3; ++c)
              inputs.plane(GlobalId::P, c)[s] = grid.origin[c] + (static_cast<float>(voxel[c]) + 0.5f) * grid.voxel_size;
          if (inputs.has(GlobalId::filter_width)) inputs.plane(GlobalId::filter_width)[s] = grid.voxel_size;
        }
      bindings.local().run(inputs.inputs(), outputs.planes(), slice);
      const std::size_t first = static_cast<std::size_t>(k) * slice;
      for (std::size_t s = 0; s < slice; ++s) {
        grid.density[first + s] = std::clamp(outputs.plane(layout.plane(OutputId::density))[s], 0.0f, 1.0f);
        if (colored)
          for (int c = 0; c < 3; ++c) grid.color[3 * (first + s) + c] = outputs.plane(layout.plane(OutputId::color, c))[s];
      }
      const long done = ++slices_done;
      if (options.progress) options.progress(ProgressCount{done, grid.size[2], done * static_cast<long>(slice)});
    });
  });
  return grid;
}

}  // namespace shadetree
