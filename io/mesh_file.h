// Triangle meshes read from OBJ and PLY files (Assimp, whose headers do
// not leave mesh_file.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

#include "graph/diagnostic.h"

namespace shadetree {

// Assimp takes about 700 bytes a triangle while it loads a file (10 M
// triangles took 7 GB): 5 M triangles keep a load near 3.5 GB, well inside
// a 24 GB machine running two renders. OBJ and PLY files are counted
// before they are loaded.
inline constexpr std::size_t max_mesh_triangles = 5'000'000;
inline constexpr std::size_t max_mesh_vertices = 3 * max_mesh_triangles;
inline constexpr std::uintmax_t max_mesh_file_bytes = 512ull << 20;
// Objects ("o") and material switches ("usemtl") of an OBJ file, together:
// Assimp's time and memory grow with the square of their count (100000
// objects took 30 s, 50000 switches 1.8 GB), and real files have far fewer.
inline constexpr std::size_t max_obj_parts = 10000;

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // empty, or one unit normal per position
  std::vector<glm::vec2> uvs;        // empty, or one per position
  std::vector<std::uint32_t> indices;  // three per triangle, each < positions.size()
};

// Every triangle of every mesh in the file, in the file's own space
// (polygons triangulated). Errors name the file: missing, unreadable, not
// a mesh, no triangles, over the size limits, NaN or infinite coordinates.
Result<TriangleMesh> load_mesh(const std::string& path);

// The mesh's bounding box, low and high corners.
inline std::pair<glm::vec3, glm::vec3> mesh_bounds(const TriangleMesh& mesh) {
  glm::vec3 low = mesh.positions.at(0), high = low;
  for (const glm::vec3& p : mesh.positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  return {low, high};
}

// Why a box cannot be scaled to a unit size in 32-bit floats (a mesh of
// one point, or 1e-30 across: the preview object's rays would start at
// 1e20, the distance grid's voxels would vanish), or empty. `use` says
// what it was for.
inline std::string too_small_to_scale(const glm::vec3& low, const glm::vec3& high, const std::string& use) {
  const glm::vec3 farthest = glm::max(glm::abs(low), glm::abs(high));
  const float extent = glm::length(high - low);
  if (extent >= 1e-5f * std::max({farthest.x, farthest.y, farthest.z, 1.0f})) return {};
  return "mesh is too small for " + use + ": its bounding box is " + std::to_string(extent) + " across";
}

}  // namespace shadetree
