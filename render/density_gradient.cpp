#include "render/density_gradient.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace shadetree {

RayFrame ray_frame(const glm::vec3& unit_direction) {
  RayFrame frame;
  frame.along = unit_direction;
  const glm::vec3 helper = std::fabs(unit_direction.x) < 0.6f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  frame.across_v = glm::normalize(glm::cross(unit_direction, helper));
  frame.across_w = glm::cross(unit_direction, frame.across_v);
  return frame;
}

glm::vec3 density_gradient(const RayFrame& frame, const GradientSamples& samples) {
  return density_gradient(frame, (samples.here - samples.previous) / samples.back,
                          across_slopes(samples.here, samples.toward_v, samples.toward_w, samples.probe));
}

}  // namespace shadetree
