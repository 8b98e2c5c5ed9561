// The pinhole (or orthographic) camera of a scene: the primary ray through
// any point of the image, so the driver can trace a pixel's neighbours for
// its footprint (ray differentials) and jittered subsamples.
#pragma once

#include "graph/scene.h"
#include "scene/ray.h"

namespace shadetree {

// Half the image plane's height: at distance 1 for a perspective camera,
// in world units for an orthographic one.
float camera_half_height(const CameraDesc& desc);

class Camera {
 public:
  // The description must be valid (parse_scene checks position != target
  // and up not parallel to the view).
  Camera(const CameraDesc& desc, int width, int height);

  // The ray through image point (x, y), in pixels from the top-left
  // corner: pixel (i, j) spans [i, i+1) x [j, j+1). Unit direction.
  Ray ray(float x, float y) const;

 private:
  glm::vec3 position_, forward_, right_, up_;
  float half_height_;  // of the image plane at distance 1 (perspective) or in world units (orthographic)
  float half_width_;
  bool orthographic_;
  int width_, height_;
};

}  // namespace shadetree
