#include "scene/camera.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace shadetree {

float camera_half_height(const CameraDesc& desc) {
  return desc.orthographic ? desc.orthographic_height / 2.0f : std::tan(desc.fov_degrees * 3.14159265358979f / 360.0f);
}

Camera::Camera(const CameraDesc& desc, int width, int height)
    : position_(desc.position[0], desc.position[1], desc.position[2]),
      orthographic_(desc.orthographic),
      width_(width),
      height_(height) {
  const glm::vec3 target(desc.target[0], desc.target[1], desc.target[2]);
  const glm::vec3 up(desc.up[0], desc.up[1], desc.up[2]);
  forward_ = glm::normalize(target - position_);
  right_ = glm::normalize(glm::cross(forward_, up));
  up_ = glm::cross(right_, forward_);
  half_height_ = camera_half_height(desc);
  half_width_ = half_height_ * static_cast<float>(width) / static_cast<float>(height);
}

Ray Camera::ray(float x, float y) const {
  const float sx = (2.0f * x / static_cast<float>(width_) - 1.0f) * half_width_;
  const float sy = (1.0f - 2.0f * y / static_cast<float>(height_)) * half_height_;
  if (orthographic_) return Ray{position_ + sx * right_ + sy * up_, forward_};
  return Ray{position_, glm::normalize(forward_ + sx * right_ + sy * up_)};
}

}  // namespace shadetree
