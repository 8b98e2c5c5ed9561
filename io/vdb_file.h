// OpenVDB files of voxel grids (io/voxel_grid.h): a fog volume "density"
// and, where the graph has one, a "color" grid, with the transform that
// puts each voxel at its place in world space; and meshes as distance
// grids. OpenVDB's headers are seen by vdb_module.cpp only.
#pragma once

#include <string>

#include "graph/diagnostic.h"
#include "nodes/distance_grid.h"
#include "io/mesh_file.h"
#include "io/voxel_grid.h"

namespace shadetree {

// Written to a temporary file and renamed into place when complete
// (io/output_file.h). Voxels of density 0 are left out (the background).
Status write_vdb(const VoxelGrid& grid, const std::string& path);

// Reads back what write_vdb wrote: the density and colour of every voxel
// of the grid's index box [0, size), as a VoxelGrid.
Result<VoxelGrid> read_vdb(const std::string& path);

// A closed mesh as a signed distance grid (OpenVDB's mesh to volume
// conversion), `resolution` voxels along the longest side of its bounding
// box padded by a tenth on every side, so that the soft region around the
// surface lies inside the grid.
Result<DistanceGrid> mesh_distance_grid(const TriangleMesh& mesh, int resolution);

}  // namespace shadetree
