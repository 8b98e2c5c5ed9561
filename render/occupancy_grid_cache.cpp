#include "render/occupancy_grid_cache.h"

#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string_view>

#include "platform/user_cache.h"

namespace shadetree {
namespace {

// Bumped whenever what a cached file holds changes.
constexpr int format_version = 1;

// Floats written exactly, as hexadecimal.
template <class Floats>
void write_floats(std::ostringstream& text, const Floats& values) {
  char number[32];
  for (float value : values) {
    std::snprintf(number, sizeof number, " %a", static_cast<double>(value));
    text << number;
  }
  text << '\n';
}

std::filesystem::path cached_file(const std::filesystem::path& folder, const EmptySpaceSource& source) {
  char name[64];
  std::snprintf(name, sizeof name, "empty_space_%016zx.bin", std::hash<std::string>{}(source.text));
  return folder / name;
}

// The line after the source: the hash of the grid's bytes, so that a file
// damaged after it was written is not read as a grid.
std::string checksum_line(std::string_view grid) {
  char line[48];
  std::snprintf(line, sizeof line, "grid %016zx\n", std::hash<std::string_view>{}(grid));
  return line;
}

}  // namespace

EmptySpaceSource empty_space_source(const ShadeIR& ir, const std::vector<OutputId>& bounded,
                                    const std::vector<float>& params, const UniformInputs& uniforms,
                                    const glm::vec3& lo, const glm::vec3& hi) {
  std::ostringstream text;
  text << "shadetree empty space " << format_version << ' ' << SHADETREE_BOUNDS_DIGEST << "\nbounds";
  write_floats(text, std::vector<float>{lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
  text << "bounded";
  for (OutputId output : bounded) text << ' ' << static_cast<int>(output);
  text << "\nuniforms";
  write_floats(text, uniforms.values);
  text << "params";
  write_floats(text, params);
  text << program_key_text(ir) << "end of source\n";
  return {text.str(), lo, hi};
}

std::optional<OccupancyGrid> read_cached_empty_space(const std::filesystem::path& folder,
                                                     const EmptySpaceSource& source) {
  if (folder.empty()) return std::nullopt;
  const std::filesystem::path path = cached_file(folder, source);
  // Nothing but the source, the checksum line and a grid's bytes.
  const std::size_t grid_size = OccupancyGrid::serialized_size();
  const std::size_t size = source.text.size() + checksum_line(std::string_view()).size() + grid_size;
  std::error_code error;
  if (std::filesystem::file_size(path, error) != size || error) return std::nullopt;
  std::ifstream file(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!file.read(bytes.data(), static_cast<std::streamsize>(size))) return std::nullopt;
  if (bytes.compare(0, source.text.size(), source.text) != 0) return std::nullopt;  // another source's
  const std::string_view grid_bytes = std::string_view(bytes).substr(size - grid_size);
  const std::string checksum = checksum_line(grid_bytes);
  if (bytes.compare(source.text.size(), checksum.size(), checksum) != 0) return std::nullopt;
  std::optional<OccupancyGrid> grid = OccupancyGrid::deserialized(source.lo, source.hi, grid_bytes);
  if (!grid) return std::nullopt;
  std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), error);  // recently used
  return grid;
}

void store_empty_space(const std::filesystem::path& folder, const EmptySpaceSource& source,
                       const OccupancyGrid& grid) {
  if (folder.empty()) return;
  const std::string bytes = grid.serialized();
  store_in_cache(folder, cached_file(folder, source).filename().string(), source.text + checksum_line(bytes) + bytes,
                 "empty_space_", cached_empty_spaces);
}

}  // namespace shadetree
