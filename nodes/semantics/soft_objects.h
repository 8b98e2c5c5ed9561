// Soft objects and generalized booleans of Perlin & Hoffert 1989, written
// once over a lane type F.
#pragma once

#include "nodes/lane_scalar.h"
#include "nodes/semantics/vec3.h"

namespace shadetree::semantics {

using namespace shadetree::lanes;

// 1989 section 2.1: D = 1 for r_x <= r - s/2, 0 for r_x >= r + s/2, and
// (r0^2 - r_x^2) / (r0^2 - r1^2) between; computed on squared radii, from
// r_x^2 (which an interval form may know more tightly than p's box does).
template <class F>
F soft_sphere_at(F distance_squared, F radius, F softness) {
  F inner = max(radius - softness * 0.5f, splat<F>(0.0f));
  F outer = radius + softness * 0.5f;
  F inner_squared = square(inner), outer_squared = square(outer);
  F ramp = (outer_squared - distance_squared) / select(outer_squared > inner_squared, outer_squared - inner_squared,
                                                       splat<F>(1.0f));
  return select(distance_squared <= inner_squared, splat<F>(1.0f),
                select(distance_squared >= outer_squared, splat<F>(0.0f), ramp));
}

template <class F>
F soft_sphere(const Vec3<F>& p, const Vec3<F>& center, F radius, F softness) {
  Vec3<F> d{p.x - center.x, p.y - center.y, p.z - center.z};
  return soft_sphere_at(length_squared(d), radius, softness);
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
  return soft_ramp(sqrt(length_squared(outside)) + inside, softness);
}

// A torus around the z axis through center.
template <class F>
F soft_torus(const Vec3<F>& p, const Vec3<F>& center, F major_radius, F minor_radius, F softness) {
  F dx = p.x - center.x, dy = p.y - center.y, dz = p.z - center.z;
  F ring = sqrt(square(dx) + square(dy)) - major_radius;
  return soft_ramp(sqrt(square(ring) + square(dz)) - minor_radius, softness);
}

// The unit vector along d, or `fallback` where d is 0 (or not finite).
template <class F>
Vec3<F> direction_or(const Vec3<F>& d, const Vec3<F>& fallback) {
  F length = sqrt(length_squared(d));
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

// A signed distance grid laid out as constant data: origin x, y, z, voxel
// size, then the voxel counts nx, ny, nz, then the distances at voxel
// centres, x fastest (nodes/distance_grid.h).
inline constexpr int distance_grid_header = 7;

// The grid's distance at p, trilinear between voxel centres. Outside the
// grid: the distance at the closest point of the grid, plus how far p lies
// beyond it (never less than the true distance's lower bound; NaN reads
// as the grid's corner).
template <class F>
F grid_distance(const float* grid, const Vec3<F>& p) {
  using I = IntOf<F>;
  const float voxel = grid[3];
  const int size[3] = {int(grid[4]), int(grid[5]), int(grid[6])};
  const float* distance = grid + distance_grid_header;
  F coordinate[3] = {p.x, p.y, p.z};
  F outside = splat<F>(0.0f);
  I cell[3];
  F weight[3];
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = grid[axis] + 0.5f * voxel, hi = grid[axis] + (float(size[axis]) - 0.5f) * voxel;
    F clamped = min(max(coordinate[axis], splat<F>(lo)), splat<F>(hi));
    F beyond = coordinate[axis] - clamped;
    outside = outside + select(beyond == beyond, square(beyond), splat<F>(0.0f));
    F position = (clamped - lo) * (1.0f / voxel);
    F base = min(floor(position), splat<F>(float(size[axis] > 1 ? size[axis] - 2 : 0)));
    cell[axis] = to_int(base);
    weight[axis] = min(position - base, splat<F>(1.0f));
  }
  const int step_y = size[0], step_z = size[0] * size[1];
  const int dx = size[0] > 1 ? 1 : 0, dy = size[1] > 1 ? step_y : 0, dz = size[2] > 1 ? step_z : 0;
  auto at = [&](I index) { return gather(distance, index); };
  I corner = cell[2] * step_z + cell[1] * step_y + cell[0];
  F c00 = at(corner) + (at(corner + dx) - at(corner)) * weight[0];
  F c10 = at(corner + dy) + (at(corner + dy + dx) - at(corner + dy)) * weight[0];
  F c01 = at(corner + dz) + (at(corner + dz + dx) - at(corner + dz)) * weight[0];
  F c11 = at(corner + dz + dy) + (at(corner + dz + dy + dx) - at(corner + dz + dy)) * weight[0];
  F c0 = c00 + (c10 - c00) * weight[1];
  F c1 = c01 + (c11 - c01) * weight[1];
  return c0 + (c1 - c0) * weight[2] + sqrt(outside);
}

// The closest point of the grid's surface to p: p - d grad d / |grad d|,
// the gradient by central differences a voxel apart (p itself where the
// gradient vanishes). The six probes are one loop, so that a kernel holds
// one copy of the grid's lookup for them, not six: its compile is a
// third of what it was (docs/architecture.md).
template <class F>
Vec3<F> grid_closest(const float* grid, const Vec3<F>& p) {
  const float h = grid[3];
  F d = grid_distance(grid, p);
  F probe[6];  // +x, -x, +y, -y, +z, -z
  for (int i = 0; i < 6; ++i) {
    const float dx = i / 2 == 0 ? h : 0.0f, dy = i / 2 == 1 ? h : 0.0f, dz = i / 2 == 2 ? h : 0.0f;
    probe[i] = grid_distance(grid, i % 2 == 0 ? Vec3<F>{p.x + dx, p.y + dy, p.z + dz}
                                              : Vec3<F>{p.x - dx, p.y - dy, p.z - dz});
  }
  Vec3<F> gradient{probe[0] - probe[1], probe[2] - probe[3], probe[4] - probe[5]};
  Vec3<F> zero{splat<F>(0.0f), splat<F>(0.0f), splat<F>(0.0f)};
  Vec3<F> n = direction_or(gradient, zero);
  return {p.x - d * n.x, p.y - d * n.y, p.z - d * n.z};
}

// 1989 section 2.2: algebraic product and sum, which keep fillets smooth.
template <class F> F soft_intersect(F a, F b) { return a * b; }
template <class F> F soft_union(F a, F b) { return a + b - a * b; }
template <class F> F soft_difference(F a, F b) { return a - a * b; }
template <class F> F soft_complement(F a) { return 1.0f - a; }

}  // namespace shadetree::semantics
