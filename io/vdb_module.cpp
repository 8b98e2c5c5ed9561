// The OpenVDB side of VDB files, built as a loadable module
// (libshadetree_vdb.so) so that only `voxelize` and the tests that read
// VDB files pay for linking OpenVDB (platform/loadable_module.h).
// io/vdb_file.cpp loads it.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <algorithm>
#include <cstdint>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

namespace {

constexpr const char* size_key = "shadetree_voxels";

void set_error(char* error, std::size_t size, const std::string& message) {
  std::snprintf(error, size, "%s", message.c_str());
}

void initialize_openvdb() {
  static std::once_flag initialized;
  std::call_once(initialized, [] { openvdb::initialize(); });
}

// Index (0, 0, 0) is the centre of the first voxel.
openvdb::math::Transform::Ptr grid_transform(const float origin[3], float voxel_size) {
  auto transform = openvdb::math::Transform::createLinearTransform(voxel_size);
  transform->postTranslate(openvdb::Vec3d(origin[0] + 0.5 * voxel_size, origin[1] + 0.5 * voxel_size,
                                          origin[2] + 0.5 * voxel_size));
  return transform;
}

std::size_t voxel_index(const int size[3], int i, int j, int k) {
  return (static_cast<std::size_t>(k) * size[1] + j) * size[0] + i;
}

}  // namespace

// Writes a fog volume "density" (voxels of density 0 left out) and, when
// `color` is not null, a "color" grid of the same voxels. 0 on success.
extern "C" int shadetree_vdb_write(const char* path, const int size[3], const float origin[3], float voxel_size,
                                   const float* density, const float* color, char* error, std::size_t error_size) {
  initialize_openvdb();
  try {
    auto densities = openvdb::FloatGrid::create(0.0f);
    densities->setName("density");
    densities->setGridClass(openvdb::GRID_FOG_VOLUME);
    densities->setTransform(grid_transform(origin, voxel_size));
    densities->insertMeta(size_key, openvdb::Vec3IMetadata(openvdb::Vec3i(size[0], size[1], size[2])));
    openvdb::Vec3SGrid::Ptr colors;
    if (color) {
      colors = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
      colors->setName("color");
      colors->setTransform(grid_transform(origin, voxel_size));
    }
    auto density_values = densities->getAccessor();
    for (int k = 0; k < size[2]; ++k)
      for (int j = 0; j < size[1]; ++j)
        for (int i = 0; i < size[0]; ++i) {
          const std::size_t v = voxel_index(size, i, j, k);
          if (density[v] <= 0.0f) continue;
          density_values.setValue(openvdb::Coord(i, j, k), density[v]);
          if (colors)
            colors->getAccessor().setValue(openvdb::Coord(i, j, k),
                                           openvdb::Vec3s(color[3 * v], color[3 * v + 1], color[3 * v + 2]));
        }
    openvdb::GridPtrVec grids{densities};
    if (colors) grids.push_back(colors);
    openvdb::io::File file(path);
    file.write(grids);
    file.close();
    return 0;
  } catch (const std::exception& exception) {
    set_error(error, error_size, exception.what());
    return 1;
  }
}

// Reads what shadetree_vdb_write wrote. The voxels are malloc'ed (release
// with shadetree_vdb_free); *color is null without a "color" grid. 0 on
// success.
extern "C" int shadetree_vdb_read(const char* path, int size[3], float origin[3], float* voxel_size, float** density,
                                  float** color, char* error, std::size_t error_size) {
  initialize_openvdb();
  *density = *color = nullptr;
  try {
    openvdb::io::File file(path);
    file.open();
    auto densities = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
    openvdb::Vec3SGrid::Ptr colors;
    if (file.hasGrid("color")) colors = openvdb::gridPtrCast<openvdb::Vec3SGrid>(file.readGrid("color"));
    file.close();
    if (!densities) {
      set_error(error, error_size, "no float grid \"density\"");
      return 1;
    }
    const auto voxels = densities->metaValue<openvdb::Vec3i>(size_key);
    for (int axis = 0; axis < 3; ++axis) size[axis] = voxels[axis];
    *voxel_size = static_cast<float>(densities->transform().voxelSize()[0]);
    const openvdb::Vec3d first = densities->transform().indexToWorld(openvdb::Coord(0, 0, 0));
    for (int axis = 0; axis < 3; ++axis) origin[axis] = static_cast<float>(first[axis] - 0.5 * *voxel_size);
    const std::size_t count = static_cast<std::size_t>(size[0]) * size[1] * size[2];
    *density = static_cast<float*>(std::malloc(count * sizeof(float)));
    if (colors) *color = static_cast<float*>(std::malloc(3 * count * sizeof(float)));
    if (!*density || (colors && !*color)) {
      std::free(*density);
      std::free(*color);
      *density = *color = nullptr;
      set_error(error, error_size, "out of memory");
      return 1;
    }
    auto density_values = densities->getConstAccessor();
    for (int k = 0; k < size[2]; ++k)
      for (int j = 0; j < size[1]; ++j)
        for (int i = 0; i < size[0]; ++i) {
          const std::size_t v = voxel_index(size, i, j, k);
          (*density)[v] = density_values.getValue(openvdb::Coord(i, j, k));
          if (!colors) continue;
          const openvdb::Vec3s rgb = colors->getConstAccessor().getValue(openvdb::Coord(i, j, k));
          for (int c = 0; c < 3; ++c) (*color)[3 * v + c] = rgb[c];
        }
    return 0;
  } catch (const std::exception& exception) {
    set_error(error, error_size, exception.what());
    return 1;
  }
}

extern "C" void shadetree_vdb_free(float* voxels) { std::free(voxels); }

// The signed distance (negative inside) of a closed triangle mesh at the
// voxel centres of a dense grid, origin + ((i, j, k) + 0.5) * voxel_size,
// into `distances` ([(k * size[1] + j) * size[0] + i]). The narrow band
// spans the whole grid, so every voxel has its distance. 0 on success.
extern "C" int shadetree_vdb_mesh_to_sdf(const float* positions, std::size_t position_count,
                                         const std::uint32_t* triangles, std::size_t triangle_count, float voxel_size,
                                         const int size[3], const float origin[3], float* distances, char* error,
                                         std::size_t error_size) {
  initialize_openvdb();
  try {
    auto transform = grid_transform(origin, voxel_size);
    std::vector<openvdb::Vec3s> points;
    points.reserve(position_count);
    for (std::size_t p = 0; p < position_count; ++p) {
      const openvdb::Vec3d index = transform->worldToIndex(
          openvdb::Vec3d(positions[3 * p], positions[3 * p + 1], positions[3 * p + 2]));
      points.emplace_back(static_cast<float>(index.x()), static_cast<float>(index.y()), static_cast<float>(index.z()));
    }
    std::vector<openvdb::Vec3I> faces;
    faces.reserve(triangle_count);
    for (std::size_t t = 0; t < triangle_count; ++t)
      faces.emplace_back(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
    const float band = static_cast<float>(std::max({size[0], size[1], size[2]})) + 1.0f;
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> mesh(points, faces);
    auto sdf = openvdb::tools::meshToVolume<openvdb::FloatGrid>(mesh, *transform, band, band);
    auto values = sdf->getConstAccessor();
    for (int k = 0; k < size[2]; ++k)
      for (int j = 0; j < size[1]; ++j)
        for (int i = 0; i < size[0]; ++i)
          distances[voxel_index(size, i, j, k)] = values.getValue(openvdb::Coord(i, j, k));
    return 0;
  } catch (const std::exception& exception) {
    set_error(error, error_size, exception.what());
    return 1;
  }
}
