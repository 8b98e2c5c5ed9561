#include "graph/scene.h"

namespace shadetree {

std::vector<LightDesc> default_lights() {
  // A key light from the upper left and in front, and a dim fill from the
  // right: the material-ball set-up of a material editor.
  LightDesc key;
  key.direction = {0.6f, -0.7f, -0.5f};
  key.intensity = 1.0f;
  LightDesc fill;
  fill.direction = {-0.8f, -0.2f, -0.3f};
  fill.color = {0.55f, 0.6f, 0.7f};
  fill.intensity = 0.35f;
  return {key, fill};
}

}  // namespace shadetree
