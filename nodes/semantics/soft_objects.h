// Soft objects and generalized booleans of Perlin & Hoffert 1989, written
// once over a lane type F.
#pragma once

#include "nodes/lane_scalar.h"
#include "nodes/semantics/vec3.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

// 1989 section 2.1: D = 1 for r_x <= r - s/2, 0 for r_x >= r + s/2, and
// (r0^2 - r_x^2) / (r0^2 - r1^2) between; computed on squared radii.
template <class F>
F soft_sphere(const Vec3<F>& p, const Vec3<F>& center, F radius, F softness) {
  Vec3<F> d{p.x - center.x, p.y - center.y, p.z - center.z};
  F inner = max(radius - softness * 0.5f, splat<F>(0.0f));
  F outer = radius + softness * 0.5f;
  F inner_squared = inner * inner, outer_squared = outer * outer;
  F distance_squared = dot3(d, d);
  F ramp = (outer_squared - distance_squared) / select(outer_squared > inner_squared, outer_squared - inner_squared,
                                                       splat<F>(1.0f));
  return select(distance_squared <= inner_squared, splat<F>(1.0f),
                select(distance_squared >= outer_squared, splat<F>(0.0f), ramp));
}

// Density from a signed distance: 1 at and below -s/2, 0 at and above s/2,
// linear between (a hard edge when s = 0).
template <class F>
F soft_ramp(F signed_distance, F softness) {
  F ramp = min(max(0.5f - signed_distance / select(softness > 0.0f, softness, splat<F>(1.0f)), splat<F>(0.0f)),
               splat<F>(1.0f));
  F hard = select(signed_distance <= 0.0f, splat<F>(1.0f), splat<F>(0.0f));
  return select(softness > 0.0f, ramp, hard);
}

template <class F>
F soft_box(const Vec3<F>& p, const Vec3<F>& center, const Vec3<F>& half_size, F softness) {
  Vec3<F> q{abs(p.x - center.x) - half_size.x, abs(p.y - center.y) - half_size.y,
            abs(p.z - center.z) - half_size.z};
  Vec3<F> outside{max(q.x, splat<F>(0.0f)), max(q.y, splat<F>(0.0f)), max(q.z, splat<F>(0.0f))};
  F inside = min(max(q.x, max(q.y, q.z)), splat<F>(0.0f));
  return soft_ramp(sqrt(dot3(outside, outside)) + inside, softness);
}

// A torus around the z axis through center.
template <class F>
F soft_torus(const Vec3<F>& p, const Vec3<F>& center, F major_radius, F minor_radius, F softness) {
  F dx = p.x - center.x, dy = p.y - center.y, dz = p.z - center.z;
  F ring = sqrt(dx * dx + dy * dy) - major_radius;
  return soft_ramp(sqrt(ring * ring + dz * dz) - minor_radius, softness);
}

// The unit vector along d, or `fallback` where d is 0 (or not finite).
template <class F>
Vec3<F> direction_or(const Vec3<F>& d, const Vec3<F>& fallback) {
  F length = sqrt(dot3(d, d));
  auto usable = both(length > 0.0f, length < 3.0e38f);
  F inverse = 1.0f / select(usable, length, splat<F>(1.0f));
  return {select(usable, d.x * inverse, fallback.x), select(usable, d.y * inverse, fallback.y),
          select(usable, d.z * inverse, fallback.z)};
}

// The point of a sphere's surface closest to p (for its centre, the top).
template <class F>
Vec3<F> closest_on_sphere(const Vec3<F>& p, const Vec3<F>& center, F radius) {
  Vec3<F> up{splat<F>(0.0f), splat<F>(1.0f), splat<F>(0.0f)};
  Vec3<F> d = direction_or(Vec3<F>{p.x - center.x, p.y - center.y, p.z - center.z}, up);
  return {center.x + radius * d.x, center.y + radius * d.y, center.z + radius * d.z};
}

// The point of a torus's surface (around the z axis through center, as
// soft_torus) closest to p: the closest point of its core circle, then the
// tube's surface toward p. On the axis, the core point on +x; on the core
// circle, the tube's outer equator.
template <class F>
Vec3<F> closest_on_torus(const Vec3<F>& p, const Vec3<F>& center, F major_radius, F minor_radius) {
  F dx = p.x - center.x, dy = p.y - center.y, dz = p.z - center.z;
  Vec3<F> ring = direction_or(Vec3<F>{dx, dy, splat<F>(0.0f)},
                              Vec3<F>{splat<F>(1.0f), splat<F>(0.0f), splat<F>(0.0f)});
  Vec3<F> core{ring.x * major_radius, ring.y * major_radius, splat<F>(0.0f)};
  Vec3<F> tube = direction_or(Vec3<F>{dx - core.x, dy - core.y, dz}, ring);
  return {center.x + core.x + minor_radius * tube.x, center.y + core.y + minor_radius * tube.y,
          center.z + minor_radius * tube.z};
}

// 1989 section 2.2: algebraic product and sum, which keep fillets smooth.
template <class F> F soft_intersect(F a, F b) { return a * b; }
template <class F> F soft_union(F a, F b) { return a + b - a * b; }
template <class F> F soft_difference(F a, F b) { return a - a * b; }
template <class F> F soft_complement(F a) { return 1.0f - a; }

}  // namespace shadetree::semantics
