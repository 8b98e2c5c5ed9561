// libFuzzer harness for what a graph pulls in and what a request names:
// the bytes as an image file (OpenImageIO, by read_image) or a mesh file
// (load_mesh, which runs Assimp in the mesh reader process) under the
// extension its first bytes suggest, and as a path into a served folder.
// Whatever they hold: no crash or sanitizer report, one-line diagnostics,
// images of at most four channels within the limit, meshes with finite
// coordinates and indices in range, and resolved paths inside the folder.
// Built by scripts/fuzz.sh beside the graph harness.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "graph/file_path.h"
#include "nodes/limits.h"
#include "io/image_output.h"
#include "io/mesh_file.h"
#include "server/served_folder.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fault(const std::string& what) {
  std::fprintf(stderr, "fuzz: %s\n", what.c_str());
  std::abort();
}

void expect_one_line(const Diagnostic& error) {
  const std::string line = error.to_string();
  if (line.find('\n') != std::string::npos || line.find('\0') != std::string::npos) fault("diagnostic of several lines");
}

// A folder of this process's own, with a graph folder inside to serve.
const fs::path& scratch() {
  static const fs::path folder = [] {
    const fs::path path = fs::temp_directory_path() / ("shadetree-file-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(path / "served" / "sub");
    return path;
  }();
  return folder;
}

std::string extension_of(const std::string& bytes) {
  if (bytes.rfind("ply", 0) == 0) return ".ply";
  if (bytes.rfind("\x89PNG", 0) == 0) return ".png";
  if (bytes.rfind("\x76\x2f\x31\x01", 0) == 0) return ".exr";
  if (bytes.rfind("II*", 0) == 0 || bytes.rfind("MM", 0) == 0) return ".tif";
  if (bytes.rfind("\xff\xd8", 0) == 0) return ".jpg";
  if (bytes.rfind("#?", 0) == 0) return ".hdr";
  return ".obj";
}

void load_as_mesh(const std::string& path) {
  Result<TriangleMesh> mesh = load_mesh(path);
  if (!mesh) return expect_one_line(mesh.error());
  for (std::uint32_t index : mesh->indices)
    if (index >= mesh->positions.size()) fault("a mesh index out of range");
  for (const glm::vec3& p : mesh->positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fault("a mesh coordinate not finite");
}

void read_as_image(const std::string& path) {
  Result<Image> image = read_image(path, max_image_pixels);
  if (!image) return expect_one_line(image.error());
  if (image->channels < 1 || image->channels > 4) fault("an image of " + std::to_string(image->channels) + " channels");
  if (static_cast<long long>(image->width) * image->height > max_image_pixels) fault("an image over the limit");
  if (image->pixels.size() != static_cast<std::size_t>(image->width) * image->height * image->channels)
    fault("an image whose pixels do not match its size");
}

void resolve_as_path(const std::string& text) {
  static const Result<ServedFolder> folder = ServedFolder::open((scratch() / "served").string());
  if (!folder) fault("cannot open the served folder");
  Result<fs::path> resolved = folder->resolve(text);
  if (!resolved) return expect_one_line(resolved.error());
  if (!check_path_text(text, "path")) fault("a path the policy refuses was resolved");
  const fs::path relative = resolved->lexically_relative(folder->path());
  if (relative.empty() || *relative.begin() == "..") fault("a path resolved outside the folder: " + resolved->string());
}

}  // namespace
}  // namespace shadetree

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shadetree;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::string extension = extension_of(bytes);
  const std::string path = (scratch() / ("input" + extension)).string();
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (extension != ".obj" && extension != ".ply") read_as_image(path);
  else load_as_mesh(path);
  if (size <= 4096) resolve_as_path(bytes);
  return 0;
}
