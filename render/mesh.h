// Triangle meshes: read from OBJ and PLY files (Assimp) and hit through
// Embree 3's BVH. Neither library's headers leave mesh_file.cpp and
// mesh_intersector.cpp.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "render/ray.h"

namespace shadetree {

inline constexpr std::size_t max_mesh_triangles = 20'000'000;
inline constexpr std::uintmax_t max_mesh_file_bytes = 1ull << 30;

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

// A mesh's BVH, built once; intersect() may be called from any thread.
class MeshIntersector {
 public:
  // The mesh must hold at least one triangle (load_mesh ensures it).
  explicit MeshIntersector(TriangleMesh mesh);
  ~MeshIntersector();
  MeshIntersector(const MeshIntersector&) = delete;
  MeshIntersector& operator=(const MeshIntersector&) = delete;

  // The nearest hit with t in [t_min, t_max]. normal: the interpolated
  // vertex normal if the mesh has normals, else the geometric normal
  // (counter-clockwise winding faces out); uv: interpolated texture
  // coordinates if the mesh has them, else the barycentric (u, v).
  std::optional<SurfaceHit> intersect(const Ray& ray, float t_min, float t_max) const;

  const TriangleMesh& mesh() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace shadetree
