// OpenVDB files of voxel grids (render/voxelize.h): a fog volume "density"
// and, where the graph has one, a "color" grid, with the transform that
// puts each voxel at its place in world space. OpenVDB's headers are seen
// by vdb_file.cpp only.
#pragma once

#include <string>

#include "graph/diagnostic.h"
#include "render/voxelize.h"

namespace shadetree {

// Written to a temporary file and renamed into place when complete
// (render/output_file.h). Voxels of density 0 are left out (the background).
Status write_vdb(const VoxelGrid& grid, const std::string& path);

// Reads back what write_vdb wrote: the density and colour of every voxel
// of the grid's index box [0, size), as a VoxelGrid.
Result<VoxelGrid> read_vdb(const std::string& path);

}  // namespace shadetree
