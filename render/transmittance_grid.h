// Cached shadows for the ray marcher: for one light, the transmittance
// from every point of the volume's bounds to the light, kept on a grid in
// the light's own space and read by every shaded sample instead of
// marching a shadow ray.
//
// Perlin & Hoffert 1989 section 3.1 (and Gilet & Dischler 2010's "Phong
// with shadows") march from each shaded sample toward each light, and
// neighbouring samples re-march nearly the same density: on the furry
// volumes nine samples in ten are shadow samples. A deep shadow map
// (Lokovic & Veach 2000) marches once from the light instead: the grid's
// rows are light rays (parallel for a directional light, fanning out
// from a point light), each marched through the bounds at the shadow step
// with the same segment compositing as the exact shadow march, storing
// the optical depth reached at each step. A lookup is trilinear between
// four neighbouring light rays and two depths: exact along the light and
// interpolated only across it, so shadows keep their depth and lose only
// detail finer than the rays' spacing.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "graph/diagnostic.h"
#include "render/occupancy_grid.h"
#include "scene/scene.h"

namespace shadetree {

// The opacity (per reference step, in [0, 1]) of the volume at each of
// `points`, each seen along its `toward_light` (the graph's I): called
// from worker threads, each with its own points.
using OpacitySampler = std::function<void(const std::vector<glm::vec3>& points,
                                          const std::vector<glm::vec3>& toward_light, std::vector<float>& opacities)>;

// How a grid is laid out and marched.
struct TransmittanceGridSpec {
  float spacing = 0.0f;         // between neighbouring light rays, in world units across the bounds
  float shadow_step = 0.0f;     // along them: the exact shadow march's step
  float reference_step = 0.0f;  // what the opacity is per (1989: alpha depends on the step)
  float termination = 0.0f;     // transmittance below this is 0, as in the exact march
  std::size_t max_values = 0;   // the grid's bound; the spacing grows to fit it
  int threads = 0;
  const std::atomic<bool>* cancel = nullptr;
  const OccupancyGrid* occupancy = nullptr;  // if set, light rays step over the empty space it finds
};

// Lookups between light rays whose transmittances differ by more than
// this are left to a shadow ray: the sharp edge of a hard surface's
// shadow, which interpolation would blur over a ray spacing. Measured on
// the gallery's volumes against exact shadows (docs/architecture.md): at
// 0.25 no image differs by more than 4/255 in more than 1% of its pixels;
// at 0.5 two do, and at 4/255 nearly every furry sample marches a ray.
inline constexpr float max_spread = 0.25f;

class TransmittanceGrid {
 public:
  // A light ray's optical depths, of which only those it gained are
  // stored: the depth is 0 until it meets the volume and stays where it
  // ended once it leaves the volume or is spent. Through a hard surface's
  // volume most of a dense grid held those (stf_bumps: 83 MB), and
  // writing them took most of the build. The stored values are framed by
  // the 0 before them and the last depth after them, so that a lookup
  // reads any value without a branch.
  struct Row {
    const float* framed = nullptr;  // value begin - 1 (0), values begin .. end - 1, value end (the last)
    int begin = 0, end = 0;

    float at(int k) const { return framed[std::clamp(k, begin - 1, end) - (begin - 1)]; }
  };

  // What `at` returns where the light rays around a point differ by more
  // than max_spread (a shadow's edge passes between them): no transmittance.
  static constexpr float edge = -1.0f;

  // Moved, never copied: the rows point into the grid's own store.
  TransmittanceGrid() = default;
  TransmittanceGrid(TransmittanceGrid&&) noexcept = default;
  TransmittanceGrid& operator=(TransmittanceGrid&&) noexcept = default;
  TransmittanceGrid(const TransmittanceGrid&) = delete;
  TransmittanceGrid& operator=(const TransmittanceGrid&) = delete;

  // The grid of `light` over the bounds [lo, hi]; none for a point light
  // inside or among the bounds, whose rays cannot be cut into one grid
  // (those are marched exactly).
  static Result<std::optional<TransmittanceGrid>> build(const Light& light, const glm::vec3& lo, const glm::vec3& hi,
                                                        const TransmittanceGridSpec& spec,
                                                        const OpacitySampler& opacity_at);

  // The fraction of the light that reaches x through the bounds, from
  // anywhere, inside or outside them; `edge` where the light rays around x
  // differ by more than max_spread (a shadow's edge passes between them).
  // A float and not an optional: returned through the stack in two parts
  // and read back as one, an optional stalled every lookup.
  float at(const glm::vec3& x) const;

  // Between neighbouring light rays, in world units at the bounds' centre.
  float spacing() const { return world_spacing_; }
  std::size_t bytes() const;
  long samples() const { return samples_; }  // opacities the build sampled
  long skipped_samples() const { return skipped_samples_; }  // in empty space

 private:
  // Light space: a light ray is (u, v); a point on it is at distance w from
  // the light (point light) or from the plane through `origin_` across the
  // light (directional light).
  // The light's frame, the bounds' extent in it and the rays' spacing
  // within the spec's bound; false for a light that cannot have a grid.
  bool lay_out(const Light& light, const glm::vec3& lo, const glm::vec3& hi, const TransmittanceGridSpec& spec);
  glm::vec3 light_space(const glm::vec3& x) const;
  glm::vec3 ray_direction(float u, float v) const;
  glm::vec3 ray_start(float u, float v) const;
  const Row& row(int i, int j) const { return rows_[static_cast<std::size_t>(j) * counts_[0] + i]; }

  bool perspective_ = false;
  glm::vec3 origin_{0.0f};  // the light's position, or a point behind the bounds as seen from it
  glm::vec3 axis_u_{1.0f, 0.0f, 0.0f}, axis_v_{0.0f, 1.0f, 0.0f}, axis_w_{0.0f, 0.0f, 1.0f};
  glm::vec3 first_{0.0f};    // (u, v, w) of the grid's first value
  glm::vec3 spacing_{1.0f};  // between values, in (u, v, w)
  glm::vec3 per_spacing_{1.0f};  // 1 / spacing_: a lookup multiplies
  float world_spacing_ = 0.0f;
  int counts_[3] = {0, 0, 0};
  std::vector<Row> rows_;  // u fastest, then v
  std::vector<std::vector<float>> gained_;  // the rows' gained depths, per tile of the build
  float spent_depth_ = 0.0f;   // where a ray's march stopped: its light is spent
  float termination_ = 0.0f;
  long samples_ = 0, skipped_samples_ = 0;
};

}  // namespace shadetree
