// The analytic objects of a scene, in their own (object) space, hit by
// their closed forms. y is up. A triangle mesh is a shape too (mesh.h).
#pragma once

#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "scene/ray.h"

namespace shadetree {

class MeshIntersector;

// Centred at the origin. uv: longitude / 2 pi from +x toward -z (so u runs
// counter-clockwise seen from +y), latitude mapped to [0, 1] from -y to +y.
struct Sphere {
  float radius = 1.0f;
};

// Perlin's donut: the circle of `major_radius` in the xz plane swept by a
// tube of `minor_radius`. uv: angle about the y axis / 2 pi (as Sphere),
// angle about the tube / 2 pi (0 on the outer equator).
struct Torus {
  float major_radius = 1.0f;
  float minor_radius = 0.4f;
};

// The plane y = 0, infinite, normal +y. uv = (x, z).
struct Plane {};

// Axis-aligned, centred at the origin. uv: the face's two other
// coordinates mapped to [0, 1] across the face.
struct Box {
  glm::vec3 half_size{1.0f};
};

// A surface of revolution about the y axis (the 1985 vase): the profile is
// a Catmull-Rom spline through (radius, height) points, its ends clamped,
// revolved a full turn. uv: angle about y / 2 pi, and the profile's
// parameter in [0, 1] from the first point to the last. Normals point away
// from the axis where the profile rises.
class Revolution {
 public:
  // At least two points, radii >= 0 (checked by the scene parser).
  explicit Revolution(std::vector<glm::vec2> profile);

  const std::vector<glm::vec2>& profile() const { return profile_; }
  // (radius, height) on the spline at profile parameter s in [0, 1].
  glm::vec2 point_at(float s) const;
  std::optional<SurfaceHit> intersect(const Ray& ray, float t_min, float t_max) const;

 private:
  // A cone frustum of the tessellated profile, from (r0, h0) to (r1, h1),
  // spanning profile parameters s0 .. s1.
  struct Segment {
    float r0, h0, r1, h1, s0, s1;
  };
  // The four spline points around profile parameter s, and t, its place between the middle two.
  struct Span {
    glm::vec2 p0, p1, p2, p3;
    float t;
  };
  Span span_at(float s) const;
  glm::vec2 tangent_at(float s) const;  // d(radius, height) / ds
  std::vector<glm::vec2> profile_;
  std::vector<Segment> segments_;
  float max_radius_ = 0.0f, min_height_ = 0.0f, max_height_ = 0.0f;
};

// A triangle mesh in its own space (mesh.h), shared between objects.
struct MeshShape {
  std::shared_ptr<const MeshIntersector> mesh;
};

using Shape = std::variant<Sphere, Torus, Plane, Box, Revolution, MeshShape>;

// Where a ray is inside the axis-aligned box [lo, hi] (Kay and Kajiya
// 1986 slabs): t from `near` to `far`, entering through a face normal to
// `near_axis` and leaving through one normal to `far_axis`. Nothing if the
// ray's line misses the box.
struct Span {
  float near = 0.0f, far = 0.0f;
  int near_axis = 0, far_axis = 0;
};
std::optional<Span> clip_to_box(const Ray& ray, const glm::vec3& lo, const glm::vec3& hi);

// The nearest hit with t in [t_min, t_max], if any.
std::optional<SurfaceHit> intersect(const Shape& shape, const Ray& ray, float t_min, float t_max);

}  // namespace shadetree
