// A triangle mesh's BVH (Embree 3, whose headers do not leave
// mesh_intersector.cpp), for the rays of the surface driver and the
// preview objects.
#pragma once

#include <memory>
#include <optional>

#include "io/mesh_file.h"
#include "scene/ray.h"

namespace shadetree {

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
