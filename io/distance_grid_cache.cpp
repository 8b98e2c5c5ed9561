#include "io/distance_grid_cache.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>

#include "io/mesh_file.h"
#include "platform/user_cache.h"

namespace shadetree {
namespace {

// Bumped whenever the grid made from a mesh changes (io/vdb_file.cpp).
constexpr int format_version = 1;
constexpr int max_side = 128;  // a grid's voxels along an axis: the largest resolution

// The whole of a file, or none where it cannot be read.
std::optional<std::string> file_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) return std::nullopt;
  return bytes;
}

// The first line of a cached grid: what it was made from, the mesh
// file's bytes by their hash (its modification time may not change
// between two writes a few milliseconds apart). Empty where the mesh file
// cannot be read or is larger than a mesh may be.
std::string source_line(const DistanceGridSource& source) {
  std::error_code error;
  const auto size = std::filesystem::file_size(source.mesh, error);
  if (error || size > max_mesh_file_bytes) return {};
  const std::optional<std::string> bytes = file_bytes(source.mesh);
  if (!bytes || bytes->size() != size) return {};
  std::ostringstream line;
  line << "shadetree distance grid " << format_version << " resolution " << source.resolution << " size " << size
       << " hash " << std::hex << std::hash<std::string>{}(*bytes) << std::dec << " mesh " << source.mesh.string()
       << "\n";
  return line.str();
}

std::filesystem::path cached_file(const std::filesystem::path& folder, const std::string& line) {
  char name[64];
  std::snprintf(name, sizeof name, "distance_grid_%016zx.bin", std::hash<std::string>{}(line));
  return folder / name;
}

template <class T>
void append(std::string& bytes, const T* values, std::size_t count) {
  bytes.append(reinterpret_cast<const char*>(values), count * sizeof(T));
}

template <class T>
bool take(const std::string& bytes, std::size_t& at, T* values, std::size_t count) {
  if (bytes.size() - at < count * sizeof(T)) return false;
  std::memcpy(values, bytes.data() + at, count * sizeof(T));
  at += count * sizeof(T);
  return true;
}

}  // namespace

std::optional<DistanceGrid> read_cached_distance_grid(const std::filesystem::path& folder,
                                                      const DistanceGridSource& source) {
  if (folder.empty()) return std::nullopt;
  const std::string line = source_line(source);
  if (line.empty()) return std::nullopt;
  const std::filesystem::path path = cached_file(folder, line);
  std::error_code error;
  constexpr std::uintmax_t most_voxels = std::uintmax_t{max_side} * max_side * max_side;
  if (std::filesystem::file_size(path, error) > line.size() + 7 * sizeof(float) + most_voxels * sizeof(float) || error)
    return std::nullopt;
  const std::optional<std::string> read = file_bytes(path);
  if (!read) return std::nullopt;
  const std::string& bytes = *read;
  if (bytes.compare(0, line.size(), line) != 0) return std::nullopt;  // another mesh, or this one changed
  std::size_t at = line.size();
  DistanceGrid grid;
  if (!take(bytes, at, grid.size.data(), 3) || !take(bytes, at, grid.origin.data(), 3) ||
      !take(bytes, at, &grid.voxel_size, 1))
    return std::nullopt;
  for (int side : grid.size)
    if (side < 1 || side > max_side) return std::nullopt;
  if (!(grid.voxel_size > 0.0f) || !std::isfinite(grid.voxel_size + grid.origin[0] + grid.origin[1] + grid.origin[2]))
    return std::nullopt;
  const std::size_t count = static_cast<std::size_t>(grid.size[0]) * grid.size[1] * grid.size[2];
  if (bytes.size() - at != count * sizeof(float)) return std::nullopt;  // cut short, or more than a grid
  grid.distance.resize(count);
  take(bytes, at, grid.distance.data(), count);
  std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), error);  // recently used
  return grid;
}

void store_distance_grid(const std::filesystem::path& folder, const DistanceGridSource& source,
                         const DistanceGrid& grid) {
  if (folder.empty()) return;
  std::string bytes = source_line(source);
  if (bytes.empty()) return;
  const std::filesystem::path path = cached_file(folder, bytes);
  append(bytes, grid.size.data(), 3);
  append(bytes, grid.origin.data(), 3);
  append(bytes, &grid.voxel_size, 1);
  append(bytes, grid.distance.data(), grid.distance.size());
  store_in_cache(folder, path.filename().string(), bytes, "distance_grid_", cached_distance_grids);
}

}  // namespace shadetree
