// The density gradient of a march sample (Perlin & Hoffert 1989 section
// 3.1): from the previous sample along the ray and two probes off it,
//   [f(x) - f(x - dx_mu), f(x + dx_v) - f(x), f(x + dx_w) - f(x)]
// in the ray's (mu, v, w) frame, carried back to (x, y, z). It costs two
// evaluations, not three, because the sample before is already known.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shadetree {

// The ray's unit direction and two unit vectors perpendicular to it and
// to each other.
struct RayFrame {
  glm::vec3 along{0.0f, 0.0f, -1.0f}, across_v{1.0f, 0.0f, 0.0f}, across_w{0.0f, 1.0f, 0.0f};
};

RayFrame ray_frame(const glm::vec3& unit_direction);

// The densities at the sample (`here`), at the previous sample `back`
// along the ray, and at the probes `probe` off it along across_v and
// across_w.
struct GradientSamples {
  float here = 0.0f;
  float previous = 0.0f, back = 1.0f;
  float toward_v = 0.0f, toward_w = 0.0f, probe = 1.0f;
};

glm::vec3 density_gradient(const RayFrame& frame, const GradientSamples& samples);

// The density's slopes across the ray (along across_v and across_w) that
// probes `probe` off it give, and the gradient from the slope along the
// ray (from the sample before) and those across it: a faint sample of the
// march takes the slopes across its ray that the ray's last probed sample
// found.
inline glm::vec2 across_slopes(float here, float toward_v, float toward_w, float probe) {
  return {(toward_v - here) / probe, (toward_w - here) / probe};
}
// The frame is orthonormal, so its transpose carries the differences back.
// Inline and a component at a time: the march takes it for every lit
// sample, and GCC's pairs of components (read as one 8-byte load) waited
// for the stores of single ones.
inline glm::vec3 density_gradient(const RayFrame& frame, float along_slope, const glm::vec2& across) {
  glm::vec3 gradient;
  for (int c = 0; c < 3; ++c)
    gradient[c] = along_slope * frame.along[c] + across.x * frame.across_v[c] + across.y * frame.across_w[c];
  return gradient;
}

}  // namespace shadetree
