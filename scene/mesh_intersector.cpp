// Ray/mesh intersection through Embree 3, the CPU ray tracing kernels: one
// device for the process, one BVH per mesh.
#include <cmath>

#include <embree3/rtcore.h>

#include <glm/geometric.hpp>

#include "scene/mesh_intersector.h"

namespace shadetree {
namespace {

RTCDevice device() {
  // Embree's verbose output and its thread affinity stay off.
  static RTCDevice shared = rtcNewDevice("verbose=0,set_affinity=0");
  return shared;
}

}  // namespace

struct MeshIntersector::State {
  TriangleMesh mesh;
  RTCScene scene = nullptr;
};

MeshIntersector::MeshIntersector(TriangleMesh mesh) : state_(std::make_unique<State>()) {
  state_->mesh = std::move(mesh);
  const TriangleMesh& m = state_->mesh;
  state_->scene = rtcNewScene(device());
  RTCGeometry geometry = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_TRIANGLE);
  // Buffers Embree allocates (and pads, as its SIMD loads need).
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                3 * sizeof(float), m.positions.size()));
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    for (int c = 0; c < 3; ++c) vertices[3 * i + c] = m.positions[i][c];
  auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), m.indices.size() / 3));
  std::copy(m.indices.begin(), m.indices.end(), indices);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(state_->scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcSetSceneBuildQuality(state_->scene, RTC_BUILD_QUALITY_HIGH);
  rtcCommitScene(state_->scene);
}

MeshIntersector::~MeshIntersector() {
  if (state_ && state_->scene) rtcReleaseScene(state_->scene);
}

const TriangleMesh& MeshIntersector::mesh() const { return state_->mesh; }

std::optional<SurfaceHit> MeshIntersector::intersect(const Ray& ray, float t_min, float t_max) const {
  // Embree asserts (and aborts) on a ray whose origin or direction is beyond
  // about 1.8e18 or not a number, or whose interval is NaN: no such ray
  // meets anything a mesh file can hold.
  constexpr float embree_large = 1.8e18f;
  for (int axis = 0; axis < 3; ++axis)
    if (!(std::fabs(ray.origin[axis]) <= embree_large) || !(std::fabs(ray.direction[axis]) <= embree_large))
      return std::nullopt;
  if (!(t_min <= t_max) || !(t_min >= 0.0f)) return std::nullopt;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray.org_x = ray.origin.x;
  query.ray.org_y = ray.origin.y;
  query.ray.org_z = ray.origin.z;
  query.ray.dir_x = ray.direction.x;
  query.ray.dir_y = ray.direction.y;
  query.ray.dir_z = ray.direction.z;
  query.ray.tnear = t_min;
  query.ray.tfar = t_max;
  query.ray.mask = 0xffffffffu;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(state_->scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  const TriangleMesh& m = state_->mesh;
  const std::uint32_t* corner = &m.indices[3 * static_cast<std::size_t>(query.hit.primID)];
  // Barycentrics: the point is (1 - u - v) v0 + u v1 + v v2.
  const float u = query.hit.u, v = query.hit.v, w = 1.0f - u - v;
  SurfaceHit hit;
  hit.t = query.ray.tfar;
  // The geometric normal from the winding (counter-clockwise faces out),
  // computed here rather than read from Embree's Ng, whose orientation
  // is Embree's own convention.
  const glm::vec3 geometric = glm::cross(m.positions[corner[1]] - m.positions[corner[0]],
                                         m.positions[corner[2]] - m.positions[corner[0]]);
  hit.normal = glm::length(geometric) > 0.0f ? glm::normalize(geometric) : glm::vec3(0.0f, 1.0f, 0.0f);
  if (!m.normals.empty()) {
    const glm::vec3 smooth = w * m.normals[corner[0]] + u * m.normals[corner[1]] + v * m.normals[corner[2]];
    if (glm::length(smooth) > 0.0f) hit.normal = glm::normalize(smooth);
  }
  hit.uv = m.uvs.empty() ? glm::vec2(u, v) : w * m.uvs[corner[0]] + u * m.uvs[corner[1]] + v * m.uvs[corner[2]];
  return hit;
}

}  // namespace shadetree
