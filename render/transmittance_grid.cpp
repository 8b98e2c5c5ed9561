#include "render/transmittance_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "render/density_gradient.h"
#include "scene/shapes.h"
#include "schedule/image_tiles.h"

namespace shadetree {
namespace {

// Light rays marched together, as a tile of the grid's (u, v) plane.
constexpr int rays_per_side = 16;

// The optical depth of a spent ray when the march has no termination:
// transmittance e^-80, below any float image's resolution.
constexpr float max_optical_depth = 80.0f;

std::array<glm::vec3, 8> corners(const glm::vec3& lo, const glm::vec3& hi) {
  std::array<glm::vec3, 8> result;
  for (int c = 0; c < 8; ++c) result[c] = {c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z};
  return result;
}

// 1989: a segment of `length` with the opacity of a reference step lets
// through (1 - opacity)^(length / reference step): its optical depth is
// -ln(1 - opacity) length / reference step.
float segment_depth(float opacity, float length, float reference_step) {
  return opacity >= 1.0f ? std::numeric_limits<float>::infinity()
                         : -std::log1p(-opacity) * (length / reference_step);
}

// One light ray of the grid being marched: value k of its row is the
// optical depth at depth first + k spacing; segment k runs from value k to
// value k + 1, where it crosses the bounds, and is sampled at its middle.
struct LightRay {
  std::size_t row = 0;  // its place in the grid's rows
  int count = 0;  // of values
  glm::vec3 start{0.0f}, direction{0.0f};
  float first = 0.0f, spacing = 0.0f;
  float near = 0.0f, far = 0.0f;  // where it crosses the bounds
  int k = 0;                      // its next segment
  float optical_depth = 0.0f;
  bool done = false;
  float occupied_until = -std::numeric_limits<float>::infinity();  // no need to look for empty space before
  int first_gained = -1;       // the first value above 0 (-1: none yet)
  std::vector<float> gained;  // the values from first_gained on

  float begin() const { return std::max(first + static_cast<float>(k) * spacing, near); }
  float end() const { return std::min(first + static_cast<float>(k + 1) * spacing, far); }
  float middle() const { return 0.5f * (begin() + end()); }

  // Past segment k, having gained `depth`, stopped at `spent`: value k + 1
  // is the depth reached, and every value after it too once the ray is
  // done (past the bounds or spent).
  void advance(float depth, float spent) {
    const float reached = end();
    optical_depth = std::min(optical_depth + depth, spent);
    if (optical_depth >= spent - 1.0f) optical_depth = spent;
    ++k;
    done = k + 1 >= count || reached >= far || optical_depth == spent;
    if (first_gained < 0) {
      if (optical_depth == 0.0f) return;
      first_gained = k;
    }
    gained.push_back(optical_depth);
  }

  // Its values from the first above 0 to the last that differs from the
  // one before, framed by a 0 and the last, appended to `store` at
  // `offset` (the row's pointer is set once the store stops growing).
  TransmittanceGrid::Row stored_in(std::vector<float>& store, std::size_t& offset) {
    while (gained.size() >= 2 && gained[gained.size() - 1] == gained[gained.size() - 2]) gained.pop_back();
    TransmittanceGrid::Row row;
    row.begin = std::max(first_gained, 0);
    row.end = row.begin + static_cast<int>(gained.size());
    offset = store.size();
    store.push_back(0.0f);
    store.insert(store.end(), gained.begin(), gained.end());
    store.push_back(gained.empty() ? 0.0f : gained.back());
    return row;
  }
};

// Segments sampled in empty space would gain no depth: the ray moves past
// them, keeping its depth.
long skip_empty_space(LightRay& ray, const OccupancyGrid& occupancy, float spent) {
  if (ray.middle() < ray.occupied_until) return 0;
  const Clearance clearance = occupancy.next_occupied(ray.start, ray.direction, ray.middle(), ray.far);
  ray.occupied_until = clearance.until;
  long skipped = 0;
  for (; !ray.done && ray.middle() < clearance.from; ++skipped) ray.advance(0.0f, spent);
  return skipped;
}

}  // namespace

Result<std::optional<TransmittanceGrid>> TransmittanceGrid::build(const Light& light, const glm::vec3& lo,
                                                                 const glm::vec3& hi,
                                                                 const TransmittanceGridSpec& spec,
                                                                 const OpacitySampler& opacity_at) {
  TransmittanceGrid grid;
  if (!grid.lay_out(light, lo, hi, spec)) return std::optional<TransmittanceGrid>();

  std::atomic<long> samples{0}, skipped{0};
  const int depth_count = grid.counts_[2];
  const int tiles_across = (grid.counts_[0] + rays_per_side - 1) / rays_per_side;
  // A light ray that misses the bounds gains nothing: 0 everywhere.
  static constexpr float nothing_gained[2] = {0.0f, 0.0f};
  grid.rows_.assign(static_cast<std::size_t>(grid.counts_[0]) * grid.counts_[1], Row{nothing_gained, 0, 0});
  grid.gained_.resize(static_cast<std::size_t>(tiles_across) * ((grid.counts_[1] + rays_per_side - 1) / rays_per_side));
  Status marched = for_each_tile(
      grid.counts_[0], grid.counts_[1], rays_per_side, spec.threads,
      [&](const Tile& tile) -> long {
        std::vector<LightRay> rays;
        for (int j = tile.y0; j < tile.y0 + tile.height; ++j)
          for (int i = tile.x0; i < tile.x0 + tile.width; ++i) {
            const float u = grid.first_.x + static_cast<float>(i) * grid.spacing_.x;
            const float v = grid.first_.y + static_cast<float>(j) * grid.spacing_.y;
            LightRay ray;
            ray.start = grid.ray_start(u, v);
            ray.direction = grid.ray_direction(u, v);
            const std::optional<Span> span = clip_to_box(Ray{ray.start, ray.direction}, lo, hi);
            if (!span || span->far <= span->near) continue;
            ray.near = span->near;
            ray.far = span->far;
            ray.row = static_cast<std::size_t>(j) * grid.counts_[0] + i;
            ray.count = depth_count;
            ray.first = grid.first_.z;
            ray.spacing = grid.spacing_.z;
            ray.k = std::clamp(static_cast<int>(std::floor((ray.near - ray.first) / ray.spacing)), 0, depth_count - 1);
            rays.push_back(ray);
          }
        std::vector<LightRay*> live;
        for (LightRay& ray : rays) live.push_back(&ray);
        std::vector<glm::vec3> points, directions;
        std::vector<float> opacities;
        long tile_samples = 0, tile_skipped = 0;
        while (!live.empty()) {
          if (spec.occupancy) {
            for (LightRay* ray : live) tile_skipped += skip_empty_space(*ray, *spec.occupancy, grid.spent_depth_);
            live.erase(std::remove_if(live.begin(), live.end(), [](const LightRay* ray) { return ray->done; }),
                       live.end());
            if (live.empty()) break;
          }
          points.clear();
          directions.clear();
          for (const LightRay* ray : live) {
            points.push_back(ray->start + ray->middle() * ray->direction);
            directions.push_back(-ray->direction);
          }
          opacities.resize(points.size());
          opacity_at(points, directions, opacities);
          tile_samples += static_cast<long>(points.size());
          for (std::size_t r = 0; r < live.size(); ++r) {
            LightRay& ray = *live[r];
            ray.advance(segment_depth(opacities[r], std::max(ray.end() - ray.begin(), 0.0f), spec.reference_step),
                        grid.spent_depth_);
          }
          live.erase(std::remove_if(live.begin(), live.end(), [](const LightRay* ray) { return ray->done; }),
                     live.end());
        }
        std::vector<float>& store = grid.gained_[static_cast<std::size_t>(tile.y0 / rays_per_side) * tiles_across +
                                                 tile.x0 / rays_per_side];
        std::vector<std::size_t> offsets(rays.size());
        for (std::size_t r = 0; r < rays.size(); ++r) grid.rows_[rays[r].row] = rays[r].stored_in(store, offsets[r]);
        for (std::size_t r = 0; r < rays.size(); ++r) grid.rows_[rays[r].row].framed = store.data() + offsets[r];
        skipped += tile_skipped;
        samples += tile_samples;
        return tile_samples;
      },
      {}, spec.cancel);
  if (!marched) return marched.error();
  grid.samples_ = samples;
  grid.skipped_samples_ = skipped;
  return std::optional<TransmittanceGrid>(std::move(grid));
}

bool TransmittanceGrid::lay_out(const Light& light, const glm::vec3& lo, const glm::vec3& hi,
                                const TransmittanceGridSpec& spec) {
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float diagonal = glm::length(hi - lo);
  perspective_ = light.type == LightType::point;
  const glm::vec3 toward = perspective_ ? centre - light.position : light.direction;
  if (!(glm::length(toward) > 0.0f)) return false;
  const RayFrame frame = ray_frame(glm::normalize(toward));
  axis_w_ = frame.along;
  axis_u_ = frame.across_v;
  axis_v_ = frame.across_w;
  origin_ = perspective_ ? light.position : centre - diagonal * axis_w_;

  // The bounds in light space. A point light's rays fan out over the
  // bounds only if all of them lie well in front of it.
  glm::vec3 low(std::numeric_limits<float>::infinity()), high(-std::numeric_limits<float>::infinity());
  for (const glm::vec3& corner : corners(lo, hi)) {
    if (perspective_ && glm::dot(corner - origin_, axis_w_) < 0.1f * diagonal)
      return false;
    const glm::vec3 c = light_space(corner);
    low = glm::min(low, c);
    high = glm::max(high, c);
  }
  // Distances from a point light: the nearest point of the bounds is not a corner.
  if (perspective_) low.z = glm::length(glm::clamp(light.position, lo, hi) - light.position);

  // Lateral spacing in world units at the bounds' centre; angular for a
  // point light.
  const float lateral =
      perspective_ ? spec.spacing / glm::dot(centre - light.position, axis_w_) : spec.spacing;
  spacing_ = {lateral, lateral, spec.shadow_step};
  const auto count = [&](int axis) {
    return std::max(2, static_cast<int>(std::ceil((high[axis] - low[axis]) / spacing_[axis])) + 1);
  };
  for (;;) {
    for (int axis = 0; axis < 3; ++axis) counts_[axis] = count(axis);
    const double values = static_cast<double>(counts_[0]) * counts_[1] * counts_[2];
    if (values <= static_cast<double>(spec.max_values)) break;
    // Over the bound: wider between rays first; coarser along them only
    // once the rays are few.
    if (counts_[0] > 2 || counts_[1] > 2) {
      spacing_.x *= 1.25f;
      spacing_.y *= 1.25f;
    } else {
      spacing_.z *= 1.25f;
    }
  }
  first_ = low;
  per_spacing_ = 1.0f / spacing_;
  world_spacing_ = spec.spacing * spacing_.x / lateral;
  // Where the light is spent (transmittance below the termination), the
  // depth stops a little past it: finite, so that a lookup between a spent
  // ray and a lit one fades over the rays' spacing as the light does.
  termination_ = spec.termination;
  spent_depth_ = spec.termination > 0.0f ? 1.0f - std::log(spec.termination) : max_optical_depth;
  return true;
}

glm::vec3 TransmittanceGrid::light_space(const glm::vec3& x) const {
  const glm::vec3 d = x - origin_;
  const float depth = glm::dot(d, axis_w_);
  if (!perspective_) return {glm::dot(d, axis_u_), glm::dot(d, axis_v_), depth};
  return {glm::dot(d, axis_u_) / depth, glm::dot(d, axis_v_) / depth, glm::length(d)};
}

glm::vec3 TransmittanceGrid::ray_direction(float u, float v) const {
  return perspective_ ? glm::normalize(axis_w_ + u * axis_u_ + v * axis_v_) : axis_w_;
}

glm::vec3 TransmittanceGrid::ray_start(float u, float v) const {
  return perspective_ ? origin_ : origin_ + u * axis_u_ + v * axis_v_;
}

std::size_t TransmittanceGrid::bytes() const {
  std::size_t floats = 0;
  for (const std::vector<float>& store : gained_) floats += store.size();
  return rows_.size() * sizeof(Row) + floats * sizeof(float);
}

float TransmittanceGrid::at(const glm::vec3& x) const {
  if (perspective_ && !(glm::dot(x - origin_, axis_w_) > 0.0f)) return 1.0f;  // behind the light
  const glm::vec3 c = light_space(x);
  if (!std::isfinite(c.x + c.y + c.z)) return 1.0f;  // a point at no finite place crosses no volume
  float index[3];
  int cell[3];
  float weight[3];
  for (int axis = 0; axis < 3; ++axis) {
    index[axis] = (c[axis] - first_[axis]) * per_spacing_[axis];
    // A light ray that passes beside the bounds crosses no volume.
    if (axis < 2 && !(index[axis] > -1.0f && index[axis] < static_cast<float>(counts_[axis]))) return 1.0f;
    index[axis] = std::clamp(index[axis], 0.0f, static_cast<float>(counts_[axis] - 1));
    cell[axis] = std::min(static_cast<int>(index[axis]), counts_[axis] - 2);
    weight[axis] = index[axis] - static_cast<float>(cell[axis]);
  }
  float least = std::numeric_limits<float>::infinity(), most = 0.0f;
  const auto along = [&](int i, int j) {
    const Row& light_ray = row(i, j);
    const float near = light_ray.at(cell[2]), far = light_ray.at(cell[2] + 1);
    least = std::min(least, near);
    most = std::max(most, far);
    return near + weight[2] * (far - near);
  };
  const auto across = [&](int j) {
    const float first = along(cell[0], j);
    return first + weight[0] * (along(cell[0] + 1, j) - first);
  };
  // Optical depth is what varies linearly across a uniform medium, as the
  // path length does, so it is what is interpolated.
  const float first = across(cell[1]);
  const float depth = first + weight[1] * (across(cell[1] + 1) - first);
  // Rays that disagree: an edge of a shadow passes between them, which
  // the interpolation would blur; the caller marches a shadow ray. Their
  // spread e^-least - e^-most = e^-least (1 - e^-(most - least)) is within
  // bounds without an exp where either factor is small enough: 0.25 is
  // above e^-1.3863 and 1 - e^-0.287.
  if (least < 1.3863f && most - least > 0.287f && std::exp(-least) - std::exp(-most) > max_spread)
    return edge;
  const float transmittance = std::exp(-depth);
  return transmittance < termination_ ? 0.0f : transmittance;
}

}  // namespace shadetree
