#include "io/vdb_file.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "graph/file_path.h"
#include "platform/loadable_module.h"
#include "io/output_file.h"

namespace shadetree {
namespace {

// The OpenVDB module (io/vdb_module.cpp), loaded on first use.
struct VdbModule {
  LoadableModule module{"libshadetree_vdb.so", "OpenVDB support"};
  int (*write)(const char*, const int*, const float*, float, const float*, const float*, char*, std::size_t) =
      module.function<int(const char*, const int*, const float*, float, const float*, const float*, char*,
                          std::size_t)>("shadetree_vdb_write");
  int (*read)(const char*, int*, float*, float*, float**, float**, char*, std::size_t) =
      module.function<int(const char*, int*, float*, float*, float**, float**, char*, std::size_t)>(
          "shadetree_vdb_read");
  void (*release)(float*) = module.function<void(float*)>("shadetree_vdb_free");
  int (*mesh_to_sdf)(const float*, std::size_t, const std::uint32_t*, std::size_t, float, const int*, const float*,
                     float*, char*, std::size_t) =
      module.function<int(const float*, std::size_t, const std::uint32_t*, std::size_t, float, const int*,
                          const float*, float*, char*, std::size_t)>("shadetree_vdb_mesh_to_sdf");
  const std::string& error = module.error();
};

const VdbModule& vdb_module() {
  static VdbModule module;
  return module;
}

}  // namespace

Status write_vdb(const VoxelGrid& grid, const std::string& path) {
  const VdbModule& module = vdb_module();
  if (!module.error.empty()) return failure(module.error);
  return write_then_rename(path, [&](const std::string& temporary) {
    char reason[512] = "";
    return module.write(temporary.c_str(), grid.size.data(), grid.origin.data(), grid.voxel_size,
                        grid.density.data(), grid.color.empty() ? nullptr : grid.color.data(), reason,
                        sizeof reason) != 0
               ? "cannot write the VDB file: " + std::string(reason)
               : std::string();
  });
}

Result<VoxelGrid> read_vdb(const std::string& path) {
  if (Status text = check_path_text(path, "VDB file"); !text) return text.error();
  const VdbModule& module = vdb_module();
  if (!module.error.empty()) return failure(module.error);
  VoxelGrid grid;
  float* density = nullptr;
  float* color = nullptr;
  char reason[512] = "";
  if (module.read(path.c_str(), grid.size.data(), grid.origin.data(), &grid.voxel_size, &density, &color, reason,
                  sizeof reason) != 0)
    return failure("\"" + path + "\": cannot read the VDB file: " + reason);
  const std::size_t count = static_cast<std::size_t>(grid.size[0]) * grid.size[1] * grid.size[2];
  grid.density.assign(density, density + count);
  if (color) grid.color.assign(color, color + 3 * count);
  module.release(density);
  module.release(color);
  return grid;
}

Result<DistanceGrid> mesh_distance_grid(const TriangleMesh& mesh, int resolution) {
  const VdbModule& module = vdb_module();
  if (!module.error.empty()) return failure(module.error);
  auto [lo, hi] = mesh_bounds(mesh);
  if (std::string problem = too_small_to_scale(lo, hi, "a distance grid"); !problem.empty()) return invalid_input(problem);
  const glm::vec3 pad = 0.1f * (hi - lo) + glm::vec3(1e-6f);
  lo -= pad;
  hi += pad;
  const float longest = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  DistanceGrid grid;
  grid.voxel_size = longest / static_cast<float>(resolution);
  for (int axis = 0; axis < 3; ++axis) {
    grid.size[axis] = std::clamp(static_cast<int>(std::ceil((hi[axis] - lo[axis]) / grid.voxel_size)), 1, resolution);
    grid.origin[axis] = lo[axis];
  }
  grid.distance.resize(static_cast<std::size_t>(grid.size[0]) * grid.size[1] * grid.size[2]);
  char reason[512] = "";
  if (module.mesh_to_sdf(&mesh.positions[0].x, mesh.positions.size(), mesh.indices.data(), mesh.indices.size() / 3,
                         grid.voxel_size, grid.size.data(), grid.origin.data(), grid.distance.data(), reason,
                         sizeof reason) != 0)
    return failure(std::string("cannot convert the mesh to a distance grid: ") + reason);
  return grid;
}

}  // namespace shadetree
