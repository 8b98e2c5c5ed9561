// Ray intersections of the analytic objects, in object space. Directions
// are not unit length (see ray.h): every t is along the given direction.
#include "scene/shapes.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "scene/mesh_intersector.h"

namespace shadetree {
namespace {

constexpr float two_pi = 6.28318530717958647f;

// Longitude about the y axis as a fraction of a turn, counter-clockwise
// seen from +y, starting at +x.
float longitude(const glm::vec3& p) {
  const float u = std::atan2(-p.z, p.x) / two_pi;
  return u < 0.0f ? u + 1.0f : u;
}

// The smaller root of a t^2 + 2 b t + c = 0 in [t_min, t_max], else the
// larger, in double precision (the quadratics of grazing rays cancel).
std::optional<double> nearest_root(double a, double b, double c, double t_min, double t_max) {
  if (a == 0.0) {
    if (b == 0.0) return std::nullopt;
    const double t = -c / (2.0 * b);
    return t >= t_min && t <= t_max ? std::optional<double>(t) : std::nullopt;
  }
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return std::nullopt;
  // Numerically stable pair (no subtraction of nearly equal terms).
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 >= t_min && t0 <= t_max) return t0;
  if (t1 >= t_min && t1 <= t_max) return t1;
  return std::nullopt;
}

std::optional<SurfaceHit> intersect_sphere(const Sphere& sphere, const Ray& ray, float t_min, float t_max) {
  const glm::dvec3 o(ray.origin), d(ray.direction);
  const double r = sphere.radius;
  std::optional<double> t = nearest_root(glm::dot(d, d), glm::dot(o, d), glm::dot(o, o) - r * r, t_min, t_max);
  if (!t) return std::nullopt;
  SurfaceHit hit;
  hit.t = static_cast<float>(*t);
  const glm::vec3 p(o + *t * d);
  hit.normal = glm::normalize(p);
  hit.uv = {longitude(p), std::asin(std::clamp(hit.normal.y, -1.0f, 1.0f)) / (two_pi / 2.0f) + 0.5f};
  return hit;
}

// The torus's exact distance function, traced with steps that never
// overshoot (Hart 1996, sphere tracing), in units of a unit direction.
float torus_distance(const Torus& torus, const glm::vec3& p) {
  const float ring = std::sqrt(p.x * p.x + p.z * p.z) - torus.major_radius;
  return std::sqrt(ring * ring + p.y * p.y) - torus.minor_radius;
}

std::optional<SurfaceHit> intersect_torus(const Torus& torus, const Ray& ray, float t_min, float t_max) {
  const float speed = glm::length(ray.direction);
  if (!(speed > 0.0f)) return std::nullopt;
  const glm::vec3 direction = ray.direction / speed;
  // Clip to the bounding sphere first: most rays miss it or start close.
  const float bound = torus.major_radius + torus.minor_radius;
  const glm::dvec3 o(ray.origin), d(direction);
  const double b = glm::dot(o, d), c = glm::dot(o, o) - double(bound) * bound;
  const double discriminant = b * b - c;
  if (discriminant <= 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  float s = std::max(t_min * speed, static_cast<float>(-b - root));
  const float s_end = std::min(t_max * speed, static_cast<float>(-b + root));
  if (s > s_end) return std::nullopt;
  const float epsilon = 1e-6f * bound;
  // Inside the tube the distance is negative: trace its absolute value.
  const float side = torus_distance(torus, ray.origin + s * direction) < 0.0f ? -1.0f : 1.0f;
  for (int step = 0; step < 1024 && s <= s_end; ++step) {
    const float distance = side * torus_distance(torus, ray.origin + s * direction);
    if (distance < epsilon) {
      SurfaceHit hit;
      hit.t = s / speed;
      if (hit.t < t_min || hit.t > t_max) return std::nullopt;
      const glm::vec3 p = ray.origin + s * direction;
      const float ring_length = std::sqrt(p.x * p.x + p.z * p.z);
      const glm::vec3 centre = ring_length > 0.0f ? glm::vec3(p.x, 0.0f, p.z) * (torus.major_radius / ring_length)
                                                  : glm::vec3(torus.major_radius, 0.0f, 0.0f);
      hit.normal = glm::normalize(p - centre);
      const float radial = glm::dot(p - centre, glm::normalize(centre));
      float v = std::atan2(p.y, radial) / two_pi;
      hit.uv = {longitude(p), v < 0.0f ? v + 1.0f : v};
      return hit;
    }
    s += std::max(distance, epsilon);
  }
  return std::nullopt;
}

std::optional<SurfaceHit> intersect_plane(const Ray& ray, float t_min, float t_max) {
  if (ray.direction.y == 0.0f) return std::nullopt;
  const float t = -ray.origin.y / ray.direction.y;
  if (!(t >= t_min && t <= t_max)) return std::nullopt;
  SurfaceHit hit;
  hit.t = t;
  hit.normal = {0.0f, 1.0f, 0.0f};
  const glm::vec3 p = ray.origin + t * ray.direction;
  hit.uv = {p.x, p.z};
  return hit;
}

// The entry is the last of the near planes, the exit the first far one.
std::optional<SurfaceHit> intersect_box(const Box& box, const Ray& ray, float t_min, float t_max) {
  const std::optional<Span> span = clip_to_box(ray, -box.half_size, box.half_size);
  if (!span) return std::nullopt;
  float t = span->near;
  int axis = span->near_axis;
  if (t < t_min) t = span->far, axis = span->far_axis;
  if (t < t_min || t > t_max) return std::nullopt;
  SurfaceHit hit;
  hit.t = t;
  const glm::vec3 p = ray.origin + t * ray.direction;
  hit.normal = glm::vec3(0.0f);
  hit.normal[axis] = p[axis] > 0.0f ? 1.0f : -1.0f;
  const int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2;
  hit.uv = {(p[a] / box.half_size[a] + 1.0f) / 2.0f, (p[b] / box.half_size[b] + 1.0f) / 2.0f};
  return hit;
}

}  // namespace

std::optional<Span> clip_to_box(const Ray& ray, const glm::vec3& lo, const glm::vec3& hi) {
  Span span{-INFINITY, INFINITY, 0, 0};
  for (int axis = 0; axis < 3; ++axis) {
    const float o = ray.origin[axis], d = ray.direction[axis];
    if (d == 0.0f) {
      if (o < lo[axis] || o > hi[axis]) return std::nullopt;
      continue;
    }
    float t0 = (lo[axis] - o) / d, t1 = (hi[axis] - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > span.near) span.near = t0, span.near_axis = axis;
    if (t1 < span.far) span.far = t1, span.far_axis = axis;
  }
  if (span.near > span.far) return std::nullopt;
  return span;
}

// Segments per span of the profile: a frustum's radius differs from the
// spline's by under 0.1% of a span's length at 24.
constexpr int segments_per_span = 24;

Revolution::Revolution(std::vector<glm::vec2> profile) : profile_(std::move(profile)) {
  const int spans = static_cast<int>(profile_.size()) - 1;
  const int count = spans * segments_per_span;
  glm::vec2 previous = point_at(0.0f);
  max_radius_ = previous.x;
  min_height_ = max_height_ = previous.y;
  for (int i = 1; i <= count; ++i) {
    const float s = static_cast<float>(i) / count;
    const glm::vec2 next = point_at(s);
    segments_.push_back({previous.x, previous.y, next.x, next.y, static_cast<float>(i - 1) / count, s});
    max_radius_ = std::max(max_radius_, next.x);
    min_height_ = std::min(min_height_, next.y);
    max_height_ = std::max(max_height_, next.y);
    previous = next;
  }
}

// Catmull-Rom through the points, the end points doubled as phantom
// neighbours; s in [0, 1] runs uniformly over the spans.
Revolution::Span Revolution::span_at(float s) const {
  const int spans = static_cast<int>(profile_.size()) - 1;
  const float x = std::clamp(s, 0.0f, 1.0f) * spans;
  const int span = std::min(static_cast<int>(x), spans - 1);
  auto at = [&](int i) { return profile_[static_cast<std::size_t>(std::clamp(i, 0, spans))]; };
  return {at(span - 1), at(span), at(span + 1), at(span + 2), x - span};
}

glm::vec2 Revolution::point_at(float s) const {
  const auto [p0, p1, p2, p3, t] = span_at(s);
  return 0.5f * ((2.0f * p1) + (-p0 + p2) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t * t +
                 (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * t * t * t);
}

glm::vec2 Revolution::tangent_at(float s) const {
  const auto [p0, p1, p2, p3, t] = span_at(s);
  return 0.5f * ((-p0 + p2) + 2.0f * (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t +
                 3.0f * (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * t * t);
}

std::optional<SurfaceHit> Revolution::intersect(const Ray& ray, float t_min, float t_max) const {
  const double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
  const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  // The bounding cylinder and slab, then per segment: only those whose
  // heights the ray passes through inside them, and whose widest radius
  // reaches the ray's closest approach to the axis.
  double enter = t_min, leave = t_max;
  const double a = dx * dx + dz * dz, b = ox * dx + oz * dz, c = ox * ox + oz * oz - double(max_radius_) * max_radius_;
  if (a > 0.0) {
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0) return std::nullopt;
    const double root = std::sqrt(discriminant);
    enter = std::max(enter, (-b - root) / a);
    leave = std::min(leave, (-b + root) / a);
  } else if (c > 0.0) {
    return std::nullopt;
  }
  if (dy != 0.0) {
    double t0 = (min_height_ - oy) / dy, t1 = (max_height_ - oy) / dy;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  } else if (oy < min_height_ || oy > max_height_) {
    return std::nullopt;
  }
  if (enter > leave) return std::nullopt;
  const double y_low = std::min(oy + enter * dy, oy + leave * dy), y_high = std::max(oy + enter * dy, oy + leave * dy);
  const double t_closest = a > 0.0 ? std::clamp(-b / a, enter, leave) : enter;
  const double x_closest = ox + t_closest * dx, z_closest = oz + t_closest * dz;
  const double closest = std::sqrt(x_closest * x_closest + z_closest * z_closest);
  double best = t_max;
  const Segment* hit_segment = nullptr;
  double hit_u = 0.0;
  for (const Segment& segment : segments_) {
    if (std::max(segment.h0, segment.h1) < y_low || std::min(segment.h0, segment.h1) > y_high ||
        std::max(segment.r0, segment.r1) < closest)
      continue;
    const double dh = segment.h1 - segment.h0, dr = segment.r1 - segment.r0;
    if (dh == 0.0) {  // an annulus in the plane y = h0
      if (dy == 0.0) continue;
      const double t = (segment.h0 - oy) / dy;
      if (!(t >= t_min && t < best)) continue;
      const double x = ox + t * dx, z = oz + t * dz, radius = std::sqrt(x * x + z * z);
      const double low = std::min(segment.r0, segment.r1), high = std::max(segment.r0, segment.r1);
      if (radius < low || radius > high || high == low) continue;
      best = t, hit_segment = &segment, hit_u = (radius - segment.r0) / dr;
      continue;
    }
    // On the frustum the radius is linear in height: r = a + b t along
    // the ray, and x^2 + z^2 = r^2 is a quadratic in t.
    const double slope = dr / dh;
    const double a = segment.r0 + slope * (oy - segment.h0), b = slope * dy;
    const double qa = dx * dx + dz * dz - b * b, qb = ox * dx + oz * dz - a * b, qc = ox * ox + oz * oz - a * a;
    double roots[2];
    int root_count = 0;
    if (qa == 0.0) {
      if (qb != 0.0) roots[root_count++] = -qc / (2.0 * qb);
    } else {
      const double discriminant = qb * qb - qa * qc;
      if (discriminant < 0.0) continue;
      const double q = -(qb + std::copysign(std::sqrt(discriminant), qb));
      roots[root_count++] = q / qa;
      if (q != 0.0) roots[root_count++] = qc / q;
    }
    for (int i = 0; i < root_count; ++i) {
      const double t = roots[i];
      if (!(t >= t_min && t < best)) continue;
      const double u = (oy + t * dy - segment.h0) / dh;
      if (u < 0.0 || u > 1.0 || a + b * t < 0.0) continue;
      best = t, hit_segment = &segment, hit_u = u;
    }
  }
  if (!hit_segment) return std::nullopt;
  SurfaceHit hit;
  hit.t = static_cast<float>(best);
  const glm::vec3 p = ray.origin + hit.t * ray.direction;
  const float s = hit_segment->s0 + static_cast<float>(hit_u) * (hit_segment->s1 - hit_segment->s0);
  const glm::vec2 tangent = tangent_at(s);
  const float ring = std::sqrt(p.x * p.x + p.z * p.z);
  const glm::vec3 radial = ring > 0.0f ? glm::vec3(p.x / ring, 0.0f, p.z / ring) : glm::vec3(1.0f, 0.0f, 0.0f);
  // Normal of the profile (dh, -dr): away from the axis where it rises.
  glm::vec3 normal = tangent.y * radial + glm::vec3(0.0f, -tangent.x, 0.0f);
  if (glm::length(normal) == 0.0f) normal = radial;
  hit.normal = glm::normalize(normal);
  hit.uv = {longitude(p), s};
  return hit;
}

std::optional<SurfaceHit> intersect(const Shape& shape, const Ray& ray, float t_min, float t_max) {
  struct Visitor {
    const Ray& ray;
    float t_min, t_max;
    std::optional<SurfaceHit> operator()(const Sphere& sphere) const { return intersect_sphere(sphere, ray, t_min, t_max); }
    std::optional<SurfaceHit> operator()(const Torus& torus) const { return intersect_torus(torus, ray, t_min, t_max); }
    std::optional<SurfaceHit> operator()(const Plane&) const { return intersect_plane(ray, t_min, t_max); }
    std::optional<SurfaceHit> operator()(const Box& box) const { return intersect_box(box, ray, t_min, t_max); }
    std::optional<SurfaceHit> operator()(const Revolution& revolution) const {
      return revolution.intersect(ray, t_min, t_max);
    }
    std::optional<SurfaceHit> operator()(const MeshShape& mesh) const { return mesh.mesh->intersect(ray, t_min, t_max); }
  };
  return std::visit(Visitor{ray, t_min, t_max}, shape);
}

}  // namespace shadetree
