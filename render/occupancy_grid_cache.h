// Volumes' empty space kept in the user's cache folder
// (platform/user_cache.h). Bounding a volume's density over the bricks
// and cells of its bounds is a fifth to a half of a cached render of the
// shape transfer function volumes (0.1-0.27 s at 256x256 on 2 cores),
// and a render with another camera, size, lights or shadow mode finds
// the same empty space. A grid is found again by everything bounding
// depends on, all written in the cached file and compared when it is
// read: the density's program, the outputs bounded, the params, the
// frame's uniform globals, the bounds, and a digest of the sources of the
// interval semantics and of bounding (so a rebuilt shadetree whose bounds
// changed never reads an older one's grids).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "ir/kernel.h"
#include "render/occupancy_grid.h"

namespace shadetree {

// What a volume's empty space is found from.
struct EmptySpaceSource {
  std::string text;  // all of it, as the cached file begins
  glm::vec3 lo{0.0f}, hi{0.0f};
};

EmptySpaceSource empty_space_source(const ShadeIR& ir, const std::vector<OutputId>& bounded,
                                    const std::vector<float>& params, const UniformInputs& uniforms,
                                    const glm::vec3& lo, const glm::vec3& hi);

// How many grids the folder keeps (each 36 KB and its program's text,
// 1.3 MB for mesh_hypertexture's, whose constants hold a distance grid).
inline constexpr int cached_empty_spaces = 64;

// The grid found from `source` before, if `folder` holds it; none for an
// empty folder, or a file that is not whole.
std::optional<OccupancyGrid> read_cached_empty_space(const std::filesystem::path& folder,
                                                     const EmptySpaceSource& source);

// Keeps `grid`, found from `source`, in `folder` (nothing for an empty one).
void store_empty_space(const std::filesystem::path& folder, const EmptySpaceSource& source,
                       const OccupancyGrid& grid);

}  // namespace shadetree
