// Meshes' distance grids kept in the user's cache folder
// (platform/user_cache.h): OpenVDB takes a second or more to turn a mesh
// of some thousands of triangles into a 64^3 grid whose narrow band spans
// all of it, and every render of a mesh graph paid it (mesh_hypertexture:
// 1.5 s of each process). A grid is found again by the mesh file's path,
// size and bytes (a hash of them) and the grid's resolution, all written
// in the cached file and checked when it is read.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "nodes/distance_grid.h"

namespace shadetree {

// What a cached grid was made from.
struct DistanceGridSource {
  std::filesystem::path mesh;  // absolute
  int resolution = 0;
};

// How many grids the folder keeps (at most 8 MB each).
inline constexpr int cached_distance_grids = 32;

// The grid made from `source` before, if `folder` holds it and the mesh
// file has not changed since; none for an empty folder.
std::optional<DistanceGrid> read_cached_distance_grid(const std::filesystem::path& folder,
                                                      const DistanceGridSource& source);

// Keeps `grid`, made from `source`, in `folder` (nothing for an empty one).
void store_distance_grid(const std::filesystem::path& folder, const DistanceGridSource& source,
                         const DistanceGrid& grid);

}  // namespace shadetree
